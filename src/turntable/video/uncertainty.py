"""The camera's uncertainty and the tracker's smooth error carried into the friction
coefficient of a tracked video.

The film of a video is measured through its calibration (`turntable.video.calibrate`): the
camera's focal length, tilt, roll, look-at point and distance (the scale), the lens's k1,
the rolling shutter's readout time and the platter's rate Omega, known with the covariance C
of the calibration.  A fit's standard error sees only the scatter of the positions about the
model; an error of the camera moves every position alike and is not in it.  The coefficient's
part from the calibration is propagated linearly: G_j = d ln c / d theta_j, by central
differences of the film made with the calibration's parameter j moved by +-1 of its standard
errors (`turntable.fit.response.fit_response`), and se_cal(ln c) = sqrt(G C G^T).  The AICc
difference that selects a model moves with the camera too, by N (H_a - H_b) for the
gradients H of ln RSS of the two models: a selection is decisive only where it stays so with
the calibration ``SELECTION_Z`` (2) of its standard errors away (`selection_spread`).

The tracker's positions also carry an error that changes smoothly with where the ball is on
the platter (its shading, its outline against what lies behind it).  A fit absorbs most of
it, so the residuals do not show it, yet it can move a coefficient that the film pins down
poorly.  It is taken as a Gaussian random field on the platter, of each coordinate alike:
rms `TRACKER_ERROR` ball radii (R), correlation length `TRACKER_LENGTH` platter radii (P), so
se_track(ln c) = sqrt(sum_ij g_i . g_j K_ij), g_i = d ln c / d(x_i, y_i)
(`turntable.fit.response.coefficient_influence`), K_ij = (TRACKER_ERROR R)^2
exp(-|p_i - p_j|^2 / (2 (TRACKER_LENGTH P)^2)).  The coefficient's standard error is
sqrt(se_stat^2 + se_cal^2 + se_track^2); where a systematic part exceeds se_stat
(`DOMINANT`), it limits the measurement, and the output says so.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable.film import Film, Setup
from turntable.fit import COEFFICIENT, FilmFit, ModelFit
from turntable.fit.response import coefficient_influence, fit_response
from turntable.fit.results import DECISIVE, SELECTION_Z
from turntable.video import camera
from turntable.video.calibrate import _At, camera_of

__all__ = [
    "DOMINANT",
    "LENS_WARNING_R",
    "TRACKER_ERROR",
    "TRACKER_LENGTH",
    "CalibrationPart",
    "calibration_parts",
    "lens_note",
    "selection_spread",
    "tracker_part",
]

#: A systematic part dominates where it is more than this times the statistical one.
DOMINANT = 1.0
#: The tracker's smooth error: rms (ball radii) and correlation length (platter radii).  The
#: rms is the largest that the coefficients of one renderer's videos give, the independent
#: ray caster's (``benchmarks/tracker_error.py``, most likely: MuJoCo's 38 videos 0.0005,
#: the project's 39 0.0007, the ray caster's 14 0.0035): sized on the other two, the ray
#: caster's were covered in 10 of 14, one 3.9 standard errors off; the error depends on the
#: scene (shading, what lies beside the ball), and a camera not seen may be like it.  The
#: length, of 0.05 to 1 tried on 16 of MuJoCo's scenes, needed the least rms of the z-scores.
TRACKER_ERROR, TRACKER_LENGTH = 0.0035, 0.1
#: Frames of the tracker's covariance computed at once (memory: this times the frames).
_CHUNK = 256
#: A lens whose k1 is not measured is named in the warnings where its uncertainty moves the
#: positions by more than this (ball radii).
LENS_WARNING_R = 0.01
#: The calibration's parameters that change the film, by name.
PARAMETERS = {
    "focal_length": _At.LOG_FOCAL,
    "tilt": _At.TILT,
    "roll": _At.ROLL,
    "look_at_x": _At.LOOK_X,
    "look_at_y": _At.LOOK_Y,
    "distance": _At.LOG_DISTANCE,
    "omega": _At.OMEGA,
    "readout": _At.READOUT,
    "lens_k1": _At.K1,
}


class CalibrationPart(NamedTuple):
    """The calibration's part of the uncertainty of ln c of one model.

    Attributes
    ----------
    stderr : float
        se_cal(ln c) = sqrt(G C G^T): the relative standard error from the calibration.
    parts : dict
        |G_j| se(theta_j) for each parameter of `PARAMETERS`: its share alone (the shares
        add in quadrature to ``stderr`` where the parameters are uncorrelated).
    log_rss_gradient : numpy.ndarray
        d ln RSS / d theta of the fit, by the calibration's parameters (`selection_spread`).
    """

    stderr: float
    parts: dict[str, float]
    log_rss_gradient: NDArray[np.float64]

    @property
    def largest(self) -> str:
        """The parameter with the largest share."""
        return max(self.parts, key=self.parts.__getitem__)


def film_with(track, theta: NDArray[np.float64]) -> tuple[Film, float]:
    """The film of a track measured with the calibration's parameters ``theta``, and its Omega.

    The same frames and images of the ball; times with that readout time, positions seen
    through that camera, y mirrored as in the track."""
    pose, readout, omega = camera_of(track.calibration, theta)
    ok = np.isfinite(track.image[:, 0])
    image = track.image[ok]
    xy = camera.sphere_centre(pose, image, track.ball_radius)
    if track.mirrored:
        xy[:, 1] *= -1
    t = track.times[ok] + readout * image[:, 1] / pose.size[1]
    return Film(t, xy[:, 0], xy[:, 1], synthetic=track.film.synthetic), abs(omega)


def _variants(track, setup: Setup, omega_measured: bool, steps: dict[str, float]):
    """The films (and setups) with each parameter moved by -step and +step."""
    theta = track.calibration.parameters
    out = []
    for name, step in steps.items():
        for sign in (-1.0, 1.0):
            moved = theta.copy()
            moved[PARAMETERS[name]] += sign * step
            data, omega = film_with(track, moved)
            out.append((data, setup._replace(omega=omega) if omega_measured else setup))
    return out


def calibration_parts(
    track, setup: Setup, model: str, *, omega_measured: bool, fit_omega: bool, fit_axis: bool
) -> CalibrationPart:
    """The calibration's part of the standard error of ln c of ``model`` fitted to the
    track's film (see the module's docstring).

    Parameters
    ----------
    track : turntable.video.track.Track
    setup : Setup
        The setup of the fit: Omega the video's (``omega_measured``) or a given one.
    model : str
    omega_measured, fit_omega, fit_axis : bool
        Whether Omega is the one the calibration measured; the options of the fit.
    """
    cal = track.calibration
    cov = cal.covariance
    se = {n: math.sqrt(max(cov[i, i], 0.0)) for n, i in PARAMETERS.items()}
    steps = {n: s for n, s in se.items() if s > 0}
    change, rss = fit_response(
        track.film,
        setup,
        model,
        _variants(track, setup, omega_measured, steps),
        fit_omega=fit_omega,
        fit_axis=fit_axis,
    )
    g, g_rss = np.zeros(_At.SIZE), np.zeros(_At.SIZE)
    for grad, moved in ((g, change), (g_rss, rss)):
        for (name, step), (down, up) in zip(steps.items(), moved.reshape(-1, 2), strict=True):
            grad[PARAMETERS[name]] = (up - down) / (2 * step)
    var = float(g @ cov @ g)
    parts = {n: abs(float(g[i])) * se[n] for n, i in PARAMETERS.items()}
    return CalibrationPart(math.sqrt(max(var, 0.0)), parts, g_rss)


def tracker_part(track, influence: NDArray[np.float64]) -> float:
    """se_track(ln c): the tracker's smooth error carried into ln c (the module's docstring).

    Parameters
    ----------
    track : turntable.video.track.Track
    influence : numpy.ndarray
        d ln c / d(x_i, y_i) of the fit of ``track.film``, shape (n, 2)
        (`turntable.fit.response.coefficient_influence`).

    Returns
    -------
    float
        The standard error of ln c from the tracker's smooth error (relative).
    """
    from scipy.spatial.distance import cdist

    xy = np.column_stack([track.film.x, track.film.y])
    scale = -0.5 / (TRACKER_LENGTH * track.platter_radius) ** 2
    var = 0.0
    for i in range(0, len(xy), _CHUNK):
        kernel = np.exp(scale * cdist(xy[i : i + _CHUNK], xy, "sqeuclidean"))
        var += float(np.sum(influence[i : i + _CHUNK] * (kernel @ influence)))
    return TRACKER_ERROR * track.ball_radius * math.sqrt(max(var, 0.0))


def widened(
    result: FilmFit, parts: dict[str, CalibrationPart], tracker: dict[str, float]
) -> FilmFit:
    """The fits with their standard errors sqrt(se_stat^2 + se_cal^2 + se_track^2) (``parts``
    and ``tracker`` by model)."""
    fits: dict[str, ModelFit] = {}
    for model, f in result.fits.items():
        log_se = math.sqrt(f.log_stderr**2 + parts[model].stderr ** 2 + tracker[model] ** 2)
        fits[model] = f._replace(log_stderr=log_se, stderr=f.coefficient * log_se)
    return result._replace(fits=fits)


def summary(
    statistical: FilmFit, parts: dict[str, CalibrationPart], tracker: dict[str, float]
) -> dict[str, dict]:
    """The three parts of each coefficient's standard error, and which dominates."""
    out = {}
    for model, f in statistical.fits.items():
        p, name = parts[model], COEFFICIENT[model]
        out[model] = {
            f"{name}_stderr_statistical": f.stderr,
            f"{name}_stderr_calibration": f.coefficient * p.stderr,
            f"{name}_stderr_tracker": f.coefficient * tracker[model],
            "calibration_dominates": bool(p.stderr > DOMINANT * f.log_stderr),
            "tracker_dominates": bool(tracker[model] > DOMINANT * f.log_stderr),
            "calibration_parts_relative": p.parts,
        }
    return out


def dominance_warning(
    model: str, f: ModelFit, p: CalibrationPart, tracker: float = 0.0
) -> str | None:
    """One line where the larger systematic part of ``model``'s standard error, the
    calibration's or the tracker's (relative), dominates the statistical one."""
    largest = max(p.stderr, tracker)
    if f.bound is not None or not largest > DOMINANT * f.log_stderr:
        return None
    name = COEFFICIENT[model]
    what = (
        f"the camera's calibration (largest part: {p.largest.replace('_', ' ')})"
        if p.stderr >= tracker
        else "the tracker's error that changes with where the ball is on the platter"
    )
    return (
        f"{what} dominates the uncertainty of {name} ({model}): +-"
        f"{f.coefficient * largest:.2g} from it against +-{f.stderr:.2g} from the scatter of "
        "the positions; the standard error reported adds all parts in quadrature"
    )


def lens_shift_radii(track) -> float:
    """The largest move of the film's positions (ball radii) when k1 moves by its standard
    error, the calibration's other parameters following it."""
    cal = track.calibration
    moved, _ = film_with(track, cal.parameters + cal.lens.shift)
    d = np.hypot(moved.x - track.film.x, moved.y - track.film.y)
    return float(np.max(d)) / track.ball_radius if d.size else 0.0


def lens_note(track) -> str | None:
    """One line where the lens's k1 is not measured and its uncertainty moves the positions
    by more than `LENS_WARNING_R`."""
    lens = track.calibration.lens
    if lens.measured:
        return None
    shift = lens_shift_radii(track)
    if not shift > LENS_WARNING_R:
        return None
    return (
        f"the lens's distortion is not measured (the mark's track gives k1 = {lens.k1:.2g} +- "
        f"{lens.k1_stderr:.2g}): the camera is taken as a pinhole's, k1 = 0 +- "
        f"{lens.spread:.2g}, which may move the positions by up to {shift:.2g} R; turntable "
        "fit carries it into the coefficient's standard error"
    )


def carry(
    track, setup: Setup, result: FilmFit, *, omega_measured: bool, fit_omega: bool, fit_axis: bool
) -> tuple[FilmFit, dict[str, dict], list[str]]:
    """The fits of a tracked video with the calibration's uncertainty and the tracker's
    smooth error carried into their standard errors; the parts by model; the warnings where
    a systematic part dominates.

    Parameters
    ----------
    track : turntable.video.track.Track
    setup : Setup
    result : FilmFit
        The fits of ``track.film`` with ``setup``.
    omega_measured, fit_omega, fit_axis : bool
        As in `calibration_parts`.
    """
    options = {"omega_measured": omega_measured, "fit_omega": fit_omega, "fit_axis": fit_axis}
    parts = {m: calibration_parts(track, setup, m, **options) for m in result.fits}
    fit_options = {"fit_omega": fit_omega, "fit_axis": fit_axis}
    tracker = {
        m: tracker_part(track, coefficient_influence(track.film, setup, m, **fit_options))
        for m in result.fits
    }
    notes = [dominance_warning(m, f, parts[m], tracker[m]) for m, f in result.fits.items()]
    result = _selection_checked(result, selection_spread(track, result, parts))
    return widened(result, parts, tracker), summary(result, parts, tracker), [n for n in notes if n]


def selection_spread(track, result: FilmFit, parts: dict[str, CalibrationPart]) -> float:
    """The standard error of the AICc difference of ``result`` from the calibration:
    sqrt(D C D^T), D = N (H_selected - H_other), H the gradients of ln RSS (0 where no
    model is selected)."""
    if result.selected is None:
        return 0.0
    other = next(m for m in result.fits if m != result.selected)
    n = result.fits[result.selected].n_observations
    d = n * (parts[result.selected].log_rss_gradient - parts[other].log_rss_gradient)
    return math.sqrt(max(float(d @ track.calibration.covariance @ d), 0.0))


def _selection_checked(result: FilmFit, spread: float) -> FilmFit:
    """``result``, not decisive where the camera's uncertainty could undo its selection."""
    if not result.decisive or result.aicc_difference - SELECTION_Z * spread >= DECISIVE:
        return result
    return result._replace(
        decisive=False,
        reason=f"the selection of {result.selected} is not decisive: the camera's calibration "
        f"moves its AICc difference ({result.aicc_difference:.3g}) by +-{spread:.2g}, and "
        f"{SELECTION_Z:g} of that would bring it below {DECISIVE:g}",
    )
