"""The two friction models as functions of their parameters: what fitting and simulation share.

`MODELS` and their `COEFFICIENT`, the number of parameters (`n_parameters`, `min_frames`)
and the model's positions in the lab frame (`positions`), from the exact closed-form
solutions (`turntable.solve`, `turntable.rolling.solve`).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate, rolling
from turntable.film import Setup, check_setup
from turntable.solution import solve

#: The two models, in the order they are reported.
MODELS = ("slipping", "rolling_resistance")
#: Name of each model's dimensionless coefficient.
COEFFICIENT = {"slipping": "mu0", "rolling_resistance": "delta"}
#: Number of free components of the initial state.
N_STATE = {"slipping": 6, "rolling_resistance": 4}
#: Range searched for each coefficient (the fit stops at these bounds and says so).
BOUNDS = {"slipping": (1e-6, 1e6), "rolling_resistance": (1e-6, 1e4)}
#: Fewest coordinates left over, :math:`N - K - 1` for the model with more parameters, for which
#: a model is selected at all (below it the AICc correction dominates the comparison).
MIN_DOF = 20


def _check_model(model: str) -> str:
    if model not in MODELS:
        raise ValueError(f"model must be one of {MODELS}; got {model!r}")
    return model


def _axis_free(model: str, fit_axis: bool) -> bool:
    """Whether the axis is a parameter: only the rolling model depends on it."""
    return bool(fit_axis) and model == "rolling_resistance"


def n_parameters(model: str, fit_omega: bool = False, fit_axis: bool = False) -> int:
    r"""Return the number p of fitted parameters of ``model``.

    The initial state (6 for slipping, 4 for rolling), :math:`\ln c`, and with ``fit_omega``
    :math:`\ln \Omega`,
    with ``fit_axis`` the axis (x, y) of the rolling model (the slipping model does not
    depend on the axis).

    Parameters
    ----------
    model : {"slipping", "rolling_resistance"}
        The model.
    fit_omega, fit_axis : bool, optional
        Whether :math:`\Omega` and (for the rolling model) the axis are fitted too.

    Returns
    -------
    int
        The number p.

    Examples
    --------
    The coefficient and the initial state (6 numbers slipping, 4 rolling), and :math:`\Omega` if
    free:

    >>> from turntable import fit
    >>> fit.n_parameters("slipping"), fit.n_parameters("rolling_resistance", fit_omega=True)
    (7, 6)
    """
    return N_STATE[_check_model(model)] + 1 + int(bool(fit_omega)) + 2 * _axis_free(model, fit_axis)


def min_frames(fit_omega: bool = False, fit_axis: bool = False) -> int:
    r"""Return the fewest frames n for which `fit_film` selects a model.

    Each frame gives :math:`N = 2n` coordinates; AICc needs :math:`N - K - 1 \ge`
    `MIN_DOF` with :math:`K = p + 1` for the model with the most parameters :math:`p`
    (`n_parameters`).

    Parameters
    ----------
    fit_omega, fit_axis : bool, optional
        Whether :math:`\Omega` and (for the rolling model) the axis are fitted too.

    Returns
    -------
    int
        The number of frames.

    Examples
    --------
    >>> from turntable import fit
    >>> fit.min_frames(), fit.min_frames(fit_omega=True)
    (15, ...)
    """
    p = max(n_parameters(m, fit_omega, fit_axis) for m in MODELS)
    return math.ceil((MIN_DOF + p + 2) / 2)


def _full_state(model: str, p: NDArray[np.float64]) -> NDArray[np.float64]:
    """The state (x, y, vx, vy, wx, wy) of the fit parameters ``p`` (rolling: on the constraint)."""
    return p if model == "slipping" else rolling.state_on_constraint(p)


def _state_parameters(model: str, state0: NDArray[np.float64]) -> NDArray[np.float64]:
    return state0.copy() if model == "slipping" else state0[:4].copy()


def _solve(model: str, z0: NDArray[np.float64], tau: NDArray[np.float64], c: float, k: float):
    if model == "slipping":
        return solve(z0, tau, c, k)
    return rolling.solve(z0, tau, c, k)


def positions(
    model: str,
    coefficient: float,
    state0: ArrayLike,
    t: ArrayLike,
    setup: Setup,
    t0: float = 0.0,
) -> NDArray[np.float64]:
    r"""Return the positions (x, y) in m of the ball's centre at times ``t``, s.

    Parameters
    ----------
    model : {"slipping", "rolling_resistance"}
        Which mechanism.
    coefficient : float
        :math:`\mu_0` or :math:`\delta`, dimensionless, > 0.
    state0 : array_like
        Dimensionless state (x, y, vx, vy, wx, wy) at time ``t0`` (units of the paper:
        length :math:`R`, time :math:`1/\Omega`, relative to the axis); on the no-slip constraint
        for the rolling model.
    t : array_like
        Times in s, from ``t0`` on.
    setup : Setup
        Ball and turntable.
    t0 : float
        Time of ``state0``, s.

    Returns
    -------
    numpy.ndarray
        Shape (len(t), 2): :math:`\mathrm{axis} + R\, r(\Omega (t - t_0))` with :math:`r` from
        `turntable.solve` or `turntable.rolling.solve`.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> fit.positions("slipping", 3.0, z0, [0.0, 1.0], setup).round(4)
    array([[0.05  , 0.    ],
           [0.0289, 0.0423]])
    """
    _check_model(model)
    setup = check_setup(setup)
    t = np.asarray(_validate._as_float_array("t", t, "a 1-D array of times"), dtype=float)
    t0 = _validate.finite_scalar("t0", t0)
    if t.ndim != 1 or not np.all(np.isfinite(t)) or np.any(t < t0):
        raise ValueError(f"t must be a 1-D array of finite times >= t0 = {t0:g} s")
    z0 = _validate.state("state0", state0)
    z = _solve(model, z0, setup.omega * (t - t0), coefficient, setup.k)
    return setup.radius * z[:, :2] + np.asarray(setup.axis)
