"""The result of ``turntable fit`` as JSON (`result_json`), and reading it back."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate
from turntable._json import finite_or_none
from turntable.film import Film, Setup, check_setup
from turntable.fit.diagnose import (
    CONSISTENCY_Z,
    Consistency,
    checked_selection,
    frame_step,
    problems,
)
from turntable.fit.models import COEFFICIENT, MIN_DOF, _check_model, positions
from turntable.fit.results import DECISIVE, NOISE_FACTOR, SELECTION_Z, WHITENESS_Z, FilmFit


def result_json(
    result: FilmFit,
    setup: Setup,
    film: Film,
    mass: float | None = None,
    source: str = "",
    check: Consistency | None = None,
) -> dict[str, Any]:
    r"""Return the fit as the JSON object that ``turntable fit`` prints.

    Parameters
    ----------
    result : FilmFit
    setup : Setup
        As given to `fit_film`.
    film : Film
        Its ``synthetic`` flag (a SYNTHETIC comment in the file) is copied to "data".
    mass : float, optional
        Mass of the ball in kg; adds the dimensional coefficients
        :math:`\mu_{0,\text{dim}} = \mu_0 m \Omega` (kg/s, force per slip velocity) and
        :math:`\delta_\text{dim} = \delta m R^2 \Omega` (kg m²/s, torque per angular
        velocity), with the model's :math:`\Omega` (the fitted one with ``fit_omega``).
    source : str
        Name of the data file.
    check : Consistency, optional
        The fit repeated with :math:`\Omega` and the axis free (`consistency`), reported under
        "consistency" and in the warnings.

    Returns
    -------
    dict
        Keys "selected", "selection", "slipping", "rolling_resistance", "consistency",
        "warnings" (`problems`), "data", "setup", "units" (README, "Fitting your own
        film").  Non-finite numbers are None.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> out = fit.result_json(fit.fit_film(film, setup), setup, film, mass=0.00411)
    >>> out["selected"], round(out["slipping"]["mu0"], 2), out["data"]["synthetic"]
    ('slipping', 2.93, True)
    """
    setup = check_setup(setup)
    fits = result.fits
    fit_omega = any(math.isfinite(f.omega_stderr) for f in fits.values())
    fit_axis = math.isfinite(fits["rolling_resistance"].axis_stderr[0])
    shown = checked_selection(result, check)
    out: dict[str, Any] = {
        "selected": result.selected,
        "selection": {
            "criterion": (
                "AICc = N ln(RSS/N) + 2 K + 2 K (K + 1) / (N - K - 1), K = p + 1; decisive "
                f"from a difference of {DECISIVE:g}, unless the fit with Omega and the axis "
                f"free contradicts the given ones (|z| > {CONSISTENCY_Z:g}) or selects the "
                f"other model, or (of a video) the camera's calibration, {SELECTION_Z:g} of its "
                f"standard errors away, would bring it below {DECISIVE:g}; no selection if "
                f"N - K - 1 < {MIN_DOF}"
            ),
            "aicc_difference": finite_or_none(result.aicc_difference),
            "akaike_weights": {m: finite_or_none(w) for m, w in result.akaike_weights.items()},
            "decisive": bool(shown.decisive),
            "reason": shown.reason or None,
        },
    }
    for model, f in fits.items():
        name = COEFFICIENT[model]
        factor, unit = 1.0, ""
        if mass is not None:
            m = _validate.positive_scalar("mass", mass)
            factor = m * f.omega * (1.0 if model == "slipping" else setup.radius**2)
            unit = "kg_per_s" if model == "slipping" else "kg_m2_per_s"
        entry: dict[str, Any] = {}
        if f.bound is None:
            lo, hi = f.ci95
            entry.update(
                {
                    name: f.coefficient,
                    f"{name}_stderr": finite_or_none(f.stderr),
                    f"{name}_relative_stderr": finite_or_none(f.log_stderr),
                    f"{name}_ci95": finite_or_none([lo, hi]),
                }
            )
            if mass is not None:
                entry[f"{name}_dim_{unit}"] = f.coefficient * factor
                entry[f"{name}_dim_stderr_{unit}"] = finite_or_none(f.stderr * factor)
                entry[f"{name}_dim_ci95_{unit}"] = [
                    finite_or_none(lo * factor),
                    finite_or_none(hi * factor),
                ]
        else:
            kind = "lower" if f.bound == "upper" else "upper"
            entry.update(
                {
                    name: None,
                    f"{name}_stderr": None,
                    f"{name}_relative_stderr": None,
                    f"{name}_ci95": None,
                    f"{name}_{kind}_limit": f.limit,
                    f"{name}_search_bound": f.coefficient,
                }
            )
            if mass is not None:
                entry[f"{name}_dim_{kind}_limit_{unit}"] = f.limit * factor
        entry.update(
            {
                "rms_residual_m": finite_or_none(f.rms_residual),
                "aic": finite_or_none(f.aic),
                "aicc": finite_or_none(f.aicc),
                "n_parameters": f.n_parameters,
                "state0": [finite_or_none(v) for v in f.state0],
                "converged": f.converged,
                "at_bound": f.at_bound,
                "omega_rad_s": f.omega,
                "omega_stderr_rad_s": finite_or_none(f.omega_stderr),
                "axis_m": list(f.axis),
                "axis_stderr_m": (
                    [finite_or_none(v) for v in f.axis_stderr]
                    if math.isfinite(f.axis_stderr[0])
                    else None
                ),
                "residual_lag1_autocorrelation": finite_or_none(f.autocorrelation),
                "residual_lag1_white_sd": finite_or_none(f.autocorrelation_sd),
                "residuals_white": f.white,
                "frame_noise_m": finite_or_none(f.noise),
                "orbital_turns": finite_or_none(
                    f.orbital_rate * f.omega * (film.t[-1] - film.t[0]) / (2.0 * math.pi)
                ),
            }
        )
        out[model] = entry
    out["consistency"] = None
    if check is not None:
        g = check.refit.fits[check.model]
        out["consistency"] = {
            "freed": list(check.freed),
            "model": check.model,
            "selected": check.refit.selected,
            "aicc_difference": finite_or_none(check.refit.aicc_difference),
            "decisive": check.refit.decisive,
            "selection_changed": check.selection_changed,
            "omega_rad_s": g.omega,
            "omega_stderr_rad_s": finite_or_none(g.omega_stderr),
            "omega_z": finite_or_none(check.omega_z),
            "axis_m": list(g.axis),
            "axis_stderr_m": [finite_or_none(v) for v in g.axis_stderr],
            "axis_z": [finite_or_none(v) for v in check.axis_z],
            "threshold_z": CONSISTENCY_Z,
        }
    out["warnings"] = problems(result, film, setup, check)
    duration = float(film.t[-1] - film.t[0])
    selected = fits[result.selected] if result.selected else None
    out["data"] = {
        "file": source,
        "synthetic": bool(getattr(film, "synthetic", False)),
        "n_frames": int(film.t.size),
        "n_observations": 2 * int(film.t.size),
        "t0_s": float(film.t[0]),
        "duration_s": duration,
        "turntable_turns": float(setup.omega * duration / (2.0 * math.pi)),
        "ball_turns": (
            finite_or_none(selected.orbital_rate * selected.omega * duration / (2.0 * math.pi))
            if selected
            else None
        ),
        "frame_step_rad": frame_step(film, setup),
    }
    out["setup"] = {
        "radius_m": setup.radius,
        "omega_rad_s": setup.omega,
        "k": setup.k,
        "axis_m": list(setup.axis),
        "fit_omega": fit_omega,
        "fit_axis": fit_axis,
        **({"mass_kg": float(mass)} if mass is not None else {}),
    }
    out["units"] = {
        "mu0": "mu0_dim / (m Omega), dimensionless",
        "delta": "delta_dim / (m R^2 Omega), dimensionless",
        "state0": (
            "dimensionless state (x, y, vx, vy, wx, wy) at t0_s: position relative to the "
            "model's axis_m in units of R, velocity in units of R Omega, spin in units of "
            "Omega (the model's omega_rad_s)"
        ),
        "stderr": (
            "from the Jacobian at the optimum and the residual variance RSS/(N - p); where "
            "the residuals are not white, the larger of the AR(1) and Newey-West estimates"
        ),
        "relative_stderr": "standard error of ln(coefficient), i.e. stderr / coefficient",
        "ci95": "95 % interval exp(ln c -+ 1.96 relative_stderr): use it when relative_stderr "
        "is not small",
        "limit": (
            "a coefficient at the end of its search range is no measurement: null, with a "
            "one-sided 95 % limit (*_lower_limit or *_upper_limit) from the profile of the RSS"
        ),
        "residual_lag1_autocorrelation": (
            "of the residuals, pooled over x and y; about 0 +- residual_lag1_white_sd for a "
            f"model that fits to the noise level; residuals_white is false beyond "
            f"{WHITENESS_Z:g} times that spread"
        ),
        "frame_noise_m": (
            "noise per coordinate from the third differences of the positions at their "
            f"times; correlated residuals more than {NOISE_FACTOR:g} times it: neither model "
            "describes the film"
        ),
        "orbital_turns": "turns of the ball about its spiral centre during the film",
        "consistency": (
            "both models fitted again with Omega and the axis free: the judged model's "
            "Omega and axis, and their distance from the given ones in standard errors "
            "(omega_z, axis_z; a warning beyond threshold_z)"
        ),
        "turntable_turns": "turns of the turntable during the film (data)",
    }
    return out


def setup_from_json(result: dict[str, Any], model: str | None = None) -> Setup:
    r"""Return the `~turntable.film.Setup` recorded in a `result_json` (``turntable fit``).

    With ``model``, :math:`\Omega` and the axis are that model's (fitted ones with ``--fit-omega``,
    ``--fit-axis``).

    Parameters
    ----------
    result : dict
        A result of `result_json` (``turntable fit``), read back from JSON.
    model : {"slipping", "rolling_resistance"}, optional
        The model whose :math:`\Omega` and axis are taken; by default the given ones.

    Returns
    -------
    Setup
        Ball and turntable.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> out = fit.result_json(fit.fit_film(film, setup), setup, film)
    >>> fit.setup_from_json(out) == setup
    True
    """
    s = result["setup"]
    omega, axis = s["omega_rad_s"], s["axis_m"]
    if model is not None:
        entry = result[_check_model(model)]
        omega, axis = entry.get("omega_rad_s", omega), entry.get("axis_m", axis)
    return check_setup(Setup(s["radius_m"], omega, s["k"], (axis[0], axis[1])))


def fitted_coefficient(result: dict[str, Any], model: str) -> float:
    """Return the coefficient with which a model's path is drawn: the fitted value, or
    where the search stopped when it is reported as a limit (``*_search_bound``).

    Parameters
    ----------
    result : dict
        A result of `result_json` (``turntable fit``), read back from JSON.
    model : {"slipping", "rolling_resistance"}
        The model.

    Returns
    -------
    float
        The dimensionless coefficient.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> out = fit.result_json(fit.fit_film(film, setup), setup, film)
    >>> print(f"{fit.fitted_coefficient(out, 'slipping'):.2f}")
    2.93
    """
    entry = result[_check_model(model)]
    name = COEFFICIENT[model]
    value = entry.get(name)
    return float(value if value is not None else entry[f"{name}_search_bound"])


def fitted_positions(result: dict[str, Any], model: str, t: ArrayLike) -> NDArray[np.float64]:
    r"""Return the positions (m) of one fitted model of a `result_json` at times ``t`` (s).

    Parameters
    ----------
    result : dict
        The JSON object of ``turntable fit``.
    model : {"slipping", "rolling_resistance"}
    t : array_like
        Times in s, not before the first frame ``result["data"]["t0_s"]``.

    Returns
    -------
    numpy.ndarray
        Shape (len(t), 2), from `positions` with the fitted coefficient, ``state0``,
        :math:`\Omega` and axis.

    Raises
    ------
    ValueError
        If the result holds no finite fit of that model.

    Examples
    --------
    >>> import numpy as np
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> out = fit.result_json(fit.fit_film(film, setup), setup, film)
    >>> xy = fit.fitted_positions(out, "slipping", film.t)
    >>> residual = xy - np.column_stack([film.x, film.y])
    >>> print(f"rms residual {(residual**2).mean() ** 0.5 * 1e3:.2f} mm")
    rms residual 0.17 mm
    """
    entry = result[_check_model(model)]
    state0 = entry["state0"]
    if any(v is None for v in state0):
        raise ValueError(f"the result holds no finite fit of the {model} model")
    return positions(
        model,
        fitted_coefficient(result, model),
        state0,
        t,
        setup_from_json(result, model),
        result["data"]["t0_s"],
    )
