"""Reference matrices of rolling without slipping, for the claims checks.

Nothing here uses the closed forms of `turntable`: the no-slip dynamics is
built from the Newton-Euler equations with the constraint u = 0 kept by a
contact force solved for numerically, and the state reached after the
initial layer from the linear conditions that define it. All matrices act
on dimensionless states z = (x, y, vx, vy, wx, wy) (length R, time 1/Omega).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

#: gamma x (.) acting on horizontal vectors.
_J = np.array([[0.0, -1.0], [1.0, 0.0]])
_I2 = np.eye(2)
_O2 = np.zeros((2, 2))


def slip_matrix() -> NDArray[np.float64]:
    """Return the 2x6 matrix S with S z = u = v + gamma x w - gamma x r (Section 1)."""
    return np.hstack([-_J, _I2, _J])


def momentum_matrix(k: float) -> NDArray[np.float64]:
    """Return the 2x6 matrix of the angular momentum about the contact point.

    Notes
    -----
    Section 2, before (2.8): k wx - vy and k wy + vx, i.e. k w + gamma x v, are
    constant along every motion with viscous friction.
    """
    return np.hstack([_O2, _J, k * _I2])


def no_slip_matrix(k: float) -> NDArray[np.float64]:
    """Return the 6x6 matrix of the no-slip dynamics (constrained Newton-Euler).

    Notes
    -----
    Without slip the contact force F keeps u = 0:
    dr/dt = v, dv/dt = F, dw/dt = -gamma x F / k. Differentiating
    u = v + gamma x w - gamma x r along the motion gives
    (I - (gamma x)^2 / k) F = gamma x v, solved here numerically for F; the
    result is linear in v. Valid on the constraint subspace S z = 0.
    """
    force = np.linalg.solve(_I2 - (_J @ _J) / k, _J)  # F = force @ v
    return np.block([[_O2, _I2, _O2], [_O2, force, _O2], [_O2, -(_J @ force) / k, _O2]])


def no_slip_projection(k: float) -> NDArray[np.float64]:
    """Return the 6x6 matrix of the state reached after the initial layer (Section 3).

    Notes
    -----
    The state z' with the same position r, the same angular momentum about the
    contact point (`momentum_matrix`) and no slip (`slip_matrix`): six linear
    conditions, solved numerically.
    """
    conditions = np.vstack([np.hstack([_I2, _O2, _O2]), momentum_matrix(k), slip_matrix()])
    keep = np.vstack([np.hstack([_I2, _O2, _O2]), momentum_matrix(k), np.zeros((2, 6))])
    return np.linalg.solve(conditions, keep)


#: The components of z, by name, for `keep_and_solve`.
PARTS = {"r": slice(0, 2), "v": slice(2, 4), "w": slice(4, 6)}


def keep_and_solve(kept: tuple[str, str], solved: str) -> NDArray[np.float64]:
    """Return the 6x6 map onto u = 0 that keeps two parts of z and solves for the third.

    Notes
    -----
    The kept parts pass unchanged; the part ``solved`` (one of "r", "v", "w") is the one
    that makes S z' = 0 (`slip_matrix`), so the map sends every state onto u = 0.
    """
    if sorted((*kept, solved)) != sorted(PARTS):
        raise ValueError(f"keep two of {sorted(PARTS)}, solve for the third; got {kept}, {solved}")
    slip = slip_matrix()
    out = np.zeros((6, 6))
    for name in kept:
        out[PARTS[name], PARTS[name]] = _I2
    rest = np.zeros((2, 6))
    for name in kept:
        rest[:, PARTS[name]] = slip[:, PARTS[name]]
    out[PARTS[solved]] = -np.linalg.solve(slip[:, PARTS[solved]], rest)
    return out
