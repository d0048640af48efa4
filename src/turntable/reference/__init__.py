"""Independent reference computations, used by the claims checks, the tests and the benchmarks.

Nothing here uses the closed forms of `turntable` (`spectrum`, `solution`, ...).  Each
quantity is recomputed another way, most of them at high precision:

- the matrix L of (1.7): from the vector equations (1.6) with cross products
  (`matrix_from_equations`), from the block form typed in sympy (`symbolic`,
  `reference_matrix`) and typed in mpmath from the exact doubles mu0, k
  (`mp_system_matrix`);
- its eigenvalues: mpmath's QR algorithm at `DPS` digits (`mp_spectrum`), the roots of
  the sympy characteristic polynomial at `ROOTS_DPS` digits (`exact_roots`), the textbook
  formula (2.4) at a precision that absorbs its cancellation (`textbook_spectrum`), and
  numpy's eigensolver (`float_spectrum`);
- the solution exp(L t) z0: mpmath's matrix exponential (`expm_trajectories`) and
  scipy's (`expm_solution`);
- the spiral centre and the modal parts: a least-squares solve (`kernel_projection`)
  and the eigendecomposition (`eig_kernel_part`, `eig_mode_part`);
- the slip velocity and the conserved quantities written out from their definitions,
  and the no-slip rate from the constraint;
- the rolling-resistance model of `turntable.rolling`, in the submodule `rolling` under
  that module's names: its 4x4 matrix read off the constrained three-dimensional
  Newton-Euler equations in mpmath (``rolling.matrix``), its eigenvalues
  (``rolling.spectrum``), its solution (``rolling.solution``), the coefficients of equal
  decay (``rolling.equal_decay_delta``) and of equal power on the same path
  (``rolling.equal_power_delta``, from an eigenvector of L) at ``rolling.DPS`` digits.

The slipping ball's references are in the submodule `slipping`; their names are
importable from `turntable.reference`.

Every function is deterministic: the same input gives the same output bit for bit.
"""

from turntable.reference import rolling
from turntable.reference.slipping import (
    DPS,
    K_BALL,
    ROOTS_DPS,
    MpSpectrum,
    Symbolic,
    conserved_by_definition,
    eig_kernel_part,
    eig_mode_part,
    exact_roots,
    expm_solution,
    expm_trajectories,
    float_spectrum,
    invariant_residual,
    kernel_projection,
    log_log_slope,
    matrix_from_equations,
    mp_decaying_distance_ratio,
    mp_spectrum,
    mp_system_matrix,
    no_slip_frequency,
    planar_rhs,
    reference_dps,
    reference_matrix,
    slip_by_definition,
    symbolic,
    symbolic_char_poly_residual,
    symbolic_matrix,
    textbook_spectrum,
)

__all__ = [
    "DPS",
    "K_BALL",
    "ROOTS_DPS",
    "MpSpectrum",
    "Symbolic",
    "conserved_by_definition",
    "eig_kernel_part",
    "eig_mode_part",
    "exact_roots",
    "expm_solution",
    "expm_trajectories",
    "float_spectrum",
    "invariant_residual",
    "kernel_projection",
    "log_log_slope",
    "matrix_from_equations",
    "mp_decaying_distance_ratio",
    "mp_spectrum",
    "mp_system_matrix",
    "no_slip_frequency",
    "planar_rhs",
    "reference_dps",
    "reference_matrix",
    "rolling",
    "slip_by_definition",
    "symbolic",
    "symbolic_char_poly_residual",
    "symbolic_matrix",
    "textbook_spectrum",
]
