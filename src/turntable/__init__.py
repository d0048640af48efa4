r"""A ball slipping with viscous friction on a uniformly rotating plane.

Exact, numerically stable solution of the linear model of T. B. Ivanova,
"The Rolling of a Homogeneous Ball with Slipping on a Horizontal Rotating
Plane", Russian Journal of Nonlinear Dynamics 15(2), 171-178 (2019).

States are :math:`z = (x, y, v_x, v_y, \omega_x, \omega_y)`, dimensionless (length
:math:`R`, time :math:`1/\Omega`, mass :math:`m`).
"""

from importlib.metadata import PackageNotFoundError, version

from turntable.limits import (
    LimitErrorFit,
    limit_error,
    limit_error_fit,
    nonholonomic_period,
    small_friction_expansion,
)
from turntable.newton_euler import NewtonEulerResult, newton_euler
from turntable.solution import (
    ModalTerms,
    conserved,
    max_time,
    modal_terms,
    no_slip_state,
    nonholonomic,
    slip_velocity,
    solve,
    spiral_centre,
)
from turntable.spectrum import (
    GOLDEN,
    Expansion,
    Peak,
    Spectrum,
    alpha1_peak,
    eigenvalues,
    large_friction_expansion,
    log_damping_ratio,
    log_growth_per_turn,
    spectrum,
    system_matrix,
)

try:
    __version__ = version("turntable")
except PackageNotFoundError:  # a source tree on sys.path, not installed
    __version__ = "0+unknown"

__all__ = [
    "GOLDEN",
    "Expansion",
    "LimitErrorFit",
    "ModalTerms",
    "NewtonEulerResult",
    "Peak",
    "Spectrum",
    "alpha1_peak",
    "conserved",
    "eigenvalues",
    "large_friction_expansion",
    "limit_error",
    "limit_error_fit",
    "log_damping_ratio",
    "log_growth_per_turn",
    "max_time",
    "modal_terms",
    "newton_euler",
    "no_slip_state",
    "nonholonomic",
    "nonholonomic_period",
    "slip_velocity",
    "small_friction_expansion",
    "solve",
    "spectrum",
    "spiral_centre",
    "system_matrix",
]
