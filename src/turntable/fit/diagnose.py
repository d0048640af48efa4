r"""What a user must know about a fit: consistency of the given :math:`\Omega` and axis, problems.

`consistency` refits with :math:`\Omega` (and the axis) free; `checked_selection` withdraws a
selection that the refit contradicts; `problems` lists in one line each what a user must
know about a fit.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from turntable.film import Film, Setup, check_setup
from turntable.fit.lsq import OMEGA_FACTOR, fit_film
from turntable.fit.models import BOUNDS, COEFFICIENT
from turntable.fit.results import FilmFit

#: Relative standard error (of :math:`\ln c`) above which a fit is not locally linear: its standard
#: error and interval are then only indicative (Fig. 8: fits reach the Cramer-Rao bound
#: below about this, and beyond a few times it their intervals miss the truth in up to half
#: the films); `problems` says so.
LINEAR_RELATIVE_ERROR = 0.2
#: A freed :math:`\Omega` or axis (`consistency`) farther than this many standard errors from the
#: given value means the given one is wrong (false alarm about 6e-5 when it is right).
CONSISTENCY_Z = 4.0
#: Frames farther apart than this in :math:`\Omega t` (rad) cannot follow the ball (it
#: turns at a rate up to :math:`\Omega`): the time unit or the rate is probably wrong.
MAX_FRAME_STEP = 1.0


def frame_step(film: Film, setup: Setup) -> float:
    r"""Return the median step :math:`\Omega (t_{i+1} - t_i)` between frames, rad (0 for one frame).

    Parameters
    ----------
    film : Film
        The film (its frame times).
    setup : Setup
        Ball and turntable (:math:`\Omega`).

    Returns
    -------
    float
        The median step, rad.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> print(f"{fit.frame_step(film, setup):.4f} rad")
    0.1167 rad
    """
    t = np.asarray(film.t, dtype=float)
    return float(setup.omega * np.median(np.diff(t))) if t.size > 1 else 0.0


class Consistency(NamedTuple):
    r"""The fit repeated with :math:`\Omega` and the axis free: are the given values right?

    Attributes
    ----------
    refit : FilmFit
        `fit_film` with ``fit_omega`` and ``fit_axis``.
    freed : tuple of str
        What was given and is now free: "omega", "axis" (the axis only matters for the
        rolling model).
    model : str
        The model judged: the one selected by the fit that is checked, else the one
        ``refit`` selects, else the one of smaller RSS.  (Not simply the one ``refit``
        selects: with the axis free the rolling model can mimic a slipping ball of large
        :math:`\mu_0`, whose spiral centre it takes for the axis, and ``refit`` may then prefer it,
        not decisively, with an axis far from the given one.)
    omega_z : float
        :math:`\Omega_\mathrm{fitted} - \Omega_\mathrm{given}` over its standard error for that
        model (nan if :math:`\Omega` was
        fitted anyway, or its error is not finite).
    axis_z : tuple of float
        The same for each coordinate of the axis (nan unless the judged model is the
        rolling one and the axis was given).
    selection_changed : bool
        Whether ``refit`` decisively selects another model than the fit it checks.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> result = fit.fit_film(film, setup)
    >>> check = fit.consistency(film, setup, result)
    >>> check.model, check.selection_changed
    ('slipping', False)
    """

    refit: FilmFit
    freed: tuple[str, ...]
    model: str
    omega_z: float
    axis_z: tuple[float, float]
    selection_changed: bool


def consistency(
    film: Film,
    setup: Setup,
    result: FilmFit,
    *,
    fit_omega: bool = False,
    fit_axis: bool = False,
) -> Consistency | None:
    r"""Check the given :math:`\Omega` and axis: fit again with them free and compare.

    Parameters
    ----------
    film, setup : Film, Setup
        As given to `fit_film`.
    result : FilmFit
        The fit to check, made with ``fit_omega`` and ``fit_axis`` as given here.
    fit_omega, fit_axis : bool
        What that fit freed already; None is returned if both were.

    Returns
    -------
    Consistency or None

    Notes
    -----
    The whiteness of the residuals (`whiteness`) detects a wrong :math:`\Omega` or axis only when
    the error it leaves is larger than the noise; a small error is partly absorbed by the
    coefficient, the initial state, or the other model (a 0.4 % error in :math:`\Omega` on a film of
    30 frames/s, 6 s, 0.3 mm noise made the rolling model fit a slipping film with white
    residuals).  The direct test is the fit with :math:`\Omega` (and the axis) free: if the given
    value is right, the fitted one scatters about it by its standard error, and
    :math:`|z| >` `CONSISTENCY_Z` happens with probability 6e-5.  Where the wrong :math:`\Omega` has
    made the other model win, the refit selects the right one again (``selection_changed`` if
    it does so decisively).

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> check = fit.consistency(film, setup, fit.fit_film(film, setup))
    >>> check.freed, bool(abs(check.omega_z) < 4)
    (('omega', 'axis'), True)
    """
    freed = tuple(n for n, fixed in (("omega", not fit_omega), ("axis", not fit_axis)) if fixed)
    if not freed:
        return None
    setup = check_setup(setup)
    refit = fit_film(film, setup, fit_omega=True, fit_axis=True)
    model = result.selected or refit.selected or min(refit.fits, key=lambda m: refit.fits[m].rss)
    f = refit.fits[model]

    def z(value: float, given: float, se: float) -> float:
        return (value - given) / se if math.isfinite(se) and se > 0 else math.nan

    omega_z = z(f.omega, setup.omega, f.omega_stderr) if "omega" in freed else math.nan
    axis_z = (math.nan, math.nan)
    if "axis" in freed and model == "rolling_resistance":
        axis_z = (
            z(f.axis[0], setup.axis[0], f.axis_stderr[0]),
            z(f.axis[1], setup.axis[1], f.axis_stderr[1]),
        )
    changed = bool(
        refit.decisive and result.selected is not None and refit.selected != result.selected
    )
    return Consistency(refit, freed, model, omega_z, axis_z, changed)


def undescribed(result: FilmFit) -> str:
    r"""Why the selected model does not describe the film ("" if it does, or none is selected).

    A selection rests on the selected model fitting the film to its noise: residuals that
    are correlated from frame to frame (`whiteness`) and far above the film's noise
    (`ModelFit.describes`) leave structure that neither model follows, and a coefficient
    at the end of its search range is no measurement (a ball moving in a straight line is
    the slipping model's :math:`\mu_0 \to 0`, but not a friction).  The AICc difference then weighs
    two wrong models, and says nothing about the friction.

    Parameters
    ----------
    result : FilmFit
        The fit of a film (`fit_film`).

    Returns
    -------
    str
        One sentence: what is wrong and what to check; "" if the selected model fits.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=4.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> fit.undescribed(fit.fit_film(film, setup))
    ''
    >>> wrong = setup._replace(omega=3.5 * 1.05)  # a rate 5 % off
    >>> fit.undescribed(fit.fit_film(film, wrong))[:36]
    'neither model describes the film: th'
    """
    if result.selected is None:
        return ""
    f = result.fits[result.selected]
    name = COEFFICIENT[result.selected]
    why = []
    if not f.describes:
        why.append(
            f"its residuals (rms {f.rms_residual:.3g} m, {f.noise_ratio:.3g} times "
            f"the film's noise) are correlated from frame to frame (lag-1 autocorrelation "
            f"{f.autocorrelation:.3g}, {abs(f.whiteness_z):.3g} times the spread of white noise)"
        )
    if f.bound is not None:
        why.append(f"{name} ran into the {f.bound} end of its search range")
    if not why:
        return ""
    return (
        f"neither model describes the film: the selected {result.selected} model does not "
        f"fit it ({'; '.join(why)}); check that the ball rolls freely on a flat platter turning "
        "at a steady rate, --omega/--rpm, --k, --axis, the sign of y and the units"
    )


def checked_selection(result: FilmFit, check: Consistency | None) -> FilmFit:
    r"""Return the fit with its selection not decisive where `consistency` contradicts it.

    Parameters
    ----------
    result : FilmFit
        The fit with the given :math:`\Omega` and axis.
    check : Consistency or None
        The same fit with them free (`consistency`).

    Returns
    -------
    FilmFit
        ``result`` itself, unless its selection is decisive and the check finds the given
        :math:`\Omega` or axis more than `CONSISTENCY_Z` standard errors from the ones the film
        prefers, or selects another model decisively with them free: then a copy with
        ``decisive`` False and ``reason`` saying why; and a copy with ``decisive`` False
        wherever the selected model does not describe the film (`undescribed`).  (A wrong
        :math:`\Omega` can make the wrong
        model win by a large AICc difference: the difference then measures the fit to the
        wrong rate, not the evidence for the model.)

    Examples
    --------
    A rate 1 % off, given to the fit of a 10 s film:

    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> camera = Camera(30.0, 2e-4, 10.0)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=2)
    >>> wrong = setup._replace(omega=3.5 * 1.01)
    >>> result = fit.fit_film(film, wrong)
    >>> checked = fit.checked_selection(result, fit.consistency(film, wrong, result))
    >>> result.decisive, checked.decisive
    (True, False)
    """
    if not result.decisive:
        return result
    failed = undescribed(result)
    if failed:
        return result._replace(decisive=False, reason=failed)
    if check is None:
        return result
    why = []
    if check.selection_changed:
        why.append(
            f"with {' and '.join(check.freed)} free the film selects {check.refit.selected} "
            "decisively"
        )
    if abs(check.omega_z) > CONSISTENCY_Z:
        why.append(f"the given Omega is {check.omega_z:+.3g} standard errors from the film's")
    if max(abs(v) for v in check.axis_z) > CONSISTENCY_Z:
        why.append(f"the given axis is more than {CONSISTENCY_Z:g} standard errors from the film's")
    if not why:
        return result
    reason = (
        f"the selection of {result.selected} is not decisive: it rests on the given Omega or "
        f"axis, which the film contradicts ({'; '.join(why)})"
    )
    return result._replace(decisive=False, reason=reason)


def problems(
    result: FilmFit, film: Film, setup: Setup, check: Consistency | None = None
) -> list[str]:
    r"""Return what a user must know about a fit, one line each (empty if nothing).

    Parameters
    ----------
    result : FilmFit
    film : Film
    setup : Setup
        As given to `fit_film` (:math:`\Omega` before any fit of it).
    check : Consistency, optional
        The fit repeated with :math:`\Omega` and the axis free (`consistency`).

    Returns
    -------
    list of str
        In this order, each where it applies: frames too far apart to follow the ball
        (:math:`\Omega\, \Delta t` above `MAX_FRAME_STEP`: a time unit or rate mistake); each fit
        that did not converge; each coefficient at a bound of `BOUNDS`, with its one-sided limit;
        each fitted :math:`\Omega` at the end of its range; a selection that is not decisive or not
        made (``FilmFit.reason``); a relative standard error above `LINEAR_RELATIVE_ERROR`
        of the selected model (of each, with none selected or a selection that is not
        decisive, `checked_selection`); residuals of the selected
        model (or, with none selected,
        of the better fit) that are not white noise (`whiteness`): far above the film's
        noise, neither model fits to the noise level (`ModelFit.describes`), at it, a
        tracker's correlated errors or a small misfit; with ``check``, a given :math:`\Omega` or
        axis more than `CONSISTENCY_Z` standard errors from the one the film prefers (judged on the
        model selected, if decisively), and a selection that changes decisively when they
        are free.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> fit.problems(fit.fit_film(film, setup), film, setup)
    []
    >>> few = film._replace(t=film.t[:10], x=film.x[:10], y=film.y[:10])
    >>> [line.split(":")[0] for line in fit.problems(fit.fit_film(few, setup), few, setup)]
    ['slipping', 'no model selected', 'rolling_resistance']
    """
    out: list[str] = []
    step = frame_step(film, setup)
    if step > MAX_FRAME_STEP:
        out.append(
            f"the turntable turns {step:.3g} rad between frames ({2 * math.pi / step:.2g} frames "
            "per turn): too few to follow the ball; check that t is in seconds and "
            "--omega/--rpm"
        )
    for model, f in result.fits.items():
        name = COEFFICIENT[model]
        if not f.converged:
            out.append(f"{model}: the least-squares fit did not converge")
        if f.bound is not None:
            lo, hi = BOUNDS[model]
            end = hi if f.bound == "upper" else lo
            other = lo if f.bound == "upper" else hi
            kind = "lower" if f.bound == "upper" else "upper"
            if math.isclose(f.limit, other, rel_tol=1e-9):
                out.append(
                    f"{model}: {name} ran into the {f.bound} end {end:g} of its search range "
                    f"and the film does not constrain it anywhere in [{lo:g}, {hi:g}]; no value "
                    f"is reported"
                )
            else:
                sign = ">" if f.bound == "upper" else "<"
                out.append(
                    f"{model}: {name} ran into the {f.bound} end {end:g} of its search range; "
                    f"the film only shows {name} {sign} {f.limit:.3g} (one-sided 95 % limit, "
                    f"reported as {name}_{kind}_limit instead of a value)"
                )
        if f.omega_at_bound:
            out.append(
                f"{model}: the fitted Omega {f.omega:.4g} rad/s ran into the end of its range "
                f"(a factor {OMEGA_FACTOR:g} from --omega/--rpm)"
            )
    if result.reason:
        out.append(result.reason)
    elif result.decisive and undescribed(result):
        out.append(undescribed(result))
    # the relative error of the selected model; of both where the selection is not decisive
    shown = checked_selection(result, check)
    for model in [shown.selected] if shown.selected and shown.decisive else list(result.fits):
        f = result.fits[model]
        if f.bound is None and not math.isfinite(f.log_stderr):
            out.append(
                f"{model}: the film does not constrain {COEFFICIENT[model]} (its standard error "
                "is not finite): the value reported is no measurement"
            )
        elif f.bound is None and f.log_stderr > LINEAR_RELATIVE_ERROR:
            out.append(
                f"{model}: the relative standard error of {COEFFICIENT[model]} is "
                f"{f.log_stderr:.2g}, above {LINEAR_RELATIVE_ERROR:g}, where the fit is no "
                "longer locally linear: its standard error and interval are only indicative "
                "and can miss the truth"
            )
    judged = result.selected or min(result.fits, key=lambda m: result.fits[m].rss)
    f = result.fits[judged]
    if not f.describes:
        out.append(
            f"neither model fits to the noise level: the residuals of the {judged} fit "
            f"(rms {f.rms_residual:.3g} m, {f.noise_ratio:.3g} times the film's "
            f"noise) are correlated from frame to frame (lag-1 autocorrelation "
            f"{f.autocorrelation:.3g}, {abs(f.whiteness_z):.3g} times its spread for white "
            "noise); check --omega/--rpm, --k, --axis and the sign of y"
        )
    elif not f.white:
        out.append(
            f"the residuals of the {judged} fit (rms {f.rms_residual:.3g} m, "
            f"{f.noise_ratio:.3g} times the film's frame-to-frame noise) are "
            f"correlated from frame to frame (lag-1 autocorrelation {f.autocorrelation:.3g}): "
            "a tracker's correlated errors, or a small misfit (check --omega/--rpm, --k, "
            "--axis); the standard errors allow for the correlation (AR(1), Newey-West)"
        )
    # Omega and the axis are judged on the model the film decisively selects: with no model
    # known, each model's freed values can wander (on a short film the rolling model with
    # the axis free mimics a slipping ball), and their linearised errors are too small.
    if check is not None and result.decisive:
        g = check.refit.fits[check.model]
        if abs(check.omega_z) > CONSISTENCY_Z:
            out.append(
                f"the film prefers Omega = {g.omega:.6g} +- {g.omega_stderr:.2g} rad/s "
                f"({check.model} model with Omega free), {check.omega_z:+.3g} standard errors "
                f"from the given {setup.omega:.6g} rad/s: check --omega/--rpm (and --k), or "
                "fit it with --fit-omega"
            )
        if max(abs(v) for v in check.axis_z) > CONSISTENCY_Z:
            out.append(
                f"the film prefers the axis at ({g.axis[0]:.4g}, {g.axis[1]:.4g}) m +- "
                f"({g.axis_stderr[0]:.2g}, {g.axis_stderr[1]:.2g}) m ({check.model} model "
                f"with the axis free), not at the given ({setup.axis[0]:.4g}, "
                f"{setup.axis[1]:.4g}) m: check --axis, or fit it with --fit-axis"
            )
    if check is not None and check.selection_changed:
        out.append(
            f"with {' and '.join(check.freed)} free the film selects {check.refit.selected} "
            f"decisively (AICc difference {check.refit.aicc_difference:.3g}), not "
            f"{result.selected}: the selection rests on the given values; rerun with "
            "--fit-omega" + (" --fit-axis" if "axis" in check.freed else "")
        )
    return out
