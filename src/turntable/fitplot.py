"""Drawing a fit of ``turntable fit``: the data, both fitted paths and the residuals.

matplotlib is not a dependency of the package: it is imported by these functions only,
when ``turntable fit --plot`` (or a figure script) asks for a drawing.
"""

from __future__ import annotations

import math
import os
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from turntable.film import Film
from turntable.fit import COEFFICIENT, MODELS, fitted_positions

#: Colour and label of each model.
STYLE = {
    "slipping": ("C0", "slipping"),
    "rolling_resistance": ("C3", "rolling resistance"),
}


def value_with_error(value: float, stderr: float | None) -> str:
    """Return "value ± stderr" rounded to the second significant digit of stderr."""
    if stderr is None or not math.isfinite(stderr) or stderr <= 0:
        return f"{value:.4g}"
    decimals = max(0, 1 - math.floor(math.log10(stderr)))
    return f"{value:.{decimals}f} ± {stderr:.{decimals}f}"


def _coefficient(result: dict[str, Any], model: str) -> str:
    name = COEFFICIENT[model]
    entry = result[model]
    symbol = {"mu0": r"$\mu_0$", "delta": r"$\delta$"}[name]
    return f"{symbol} = {value_with_error(entry[name], entry[name + '_stderr'])}"


def _label(result: dict[str, Any], model: str) -> str:
    return f"{STYLE[model][1]}: {_coefficient(result, model)}"


def moving_rms(values: np.ndarray, window: int) -> np.ndarray:
    """Return the rms of ``values`` over a centred window of ``window`` samples.

    Near the ends the window holds fewer samples; the mean is over those it holds.
    """
    window = max(1, min(int(window), values.size))
    kernel = np.ones(window)
    total = np.convolve(values**2, kernel, mode="same")
    count = np.convolve(np.ones(values.size), kernel, mode="same")
    return np.sqrt(total / count)


def draw_paths(ax: Any, film: Film, result: dict[str, Any], n_curve: int = 3000) -> None:
    """Draw the tracked positions (mm) and the path of each fitted model on ``ax``."""
    t = np.linspace(film.t[0], film.t[-1], max(n_curve, film.t.size))
    ax.plot(1e3 * film.x, 1e3 * film.y, ".", color="0.6", ms=1.5, label="data")
    for model in MODELS:
        xy = fitted_positions(result, model, t)
        color, _ = STYLE[model]
        ax.plot(1e3 * xy[:, 0], 1e3 * xy[:, 1], color=color, lw=0.8, label=_label(result, model))
    axis = result["setup"]["axis_m"]
    ax.plot(1e3 * axis[0], 1e3 * axis[1], "k+", ms=8, label="axis")
    ax.set(aspect="equal", xlabel="$x$ (mm)", ylabel="$y$ (mm)")


def draw_residuals(
    ax: Any, film: Film, result: dict[str, Any], windows: int = 100, coefficients: bool = False
) -> None:
    """Draw the residuals of each fit against time on ``ax``.

    Each frame's residual per coordinate, sqrt(|data - fit|^2 / 2) in mm, as faint
    points, and its rms over a moving window of 1/``windows`` of the film as a line: the
    fit of the right model stays flat at the tracking noise, a wrong one shows structure.
    The labels give each fit's rms residual and its model or, if ``coefficients``, its
    coefficient.
    """
    window = max(1, film.t.size // windows)
    for model in MODELS:
        xy = fitted_positions(result, model, film.t)
        per_coordinate = np.hypot(film.x - xy[:, 0], film.y - xy[:, 1]) / math.sqrt(2.0)
        color, label = STYLE[model]
        rms = result[model]["rms_residual_m"]
        label = f"{label}, rms {1e3 * rms:.3g} mm"
        if coefficients:
            label = f"{_coefficient(result, model)}\nrms {1e3 * rms:.3g} mm"
        ax.semilogy(film.t, 1e3 * per_coordinate, ".", color=color, ms=1.0, alpha=0.25)
        ax.semilogy(
            film.t,
            1e3 * moving_rms(per_coordinate, window),
            color=color,
            lw=1.2,
            label=label,
        )
    ax.set(xlabel="$t$ (s)", ylabel="residual per coordinate (mm)")


def plot_fit(path: str | os.PathLike[str], film: Film, result: dict[str, Any]) -> None:
    """Write a figure of the fit to ``path`` (format from its suffix), atomically.

    Left: the data and both fitted paths; right: the residuals against time.  The title
    names the selected model and the AIC difference.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax_p, ax_r) = plt.subplots(1, 2, figsize=(10.0, 4.6), layout="constrained")
    draw_paths(ax_p, film, result)
    draw_residuals(ax_r, film, result)
    ax_p.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.15), ncols=2)
    ax_r.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.15), ncols=2)
    sel = result["selection"]
    fig.suptitle(
        f"{result['data']['file']}: selected {STYLE[result['selected']][1]} "
        f"(AIC difference {sel['aic_difference']:.3g}, Akaike weight "
        f"{sel['akaike_weights'][result['selected']]:.3g})",
        fontsize=9,
    )
    path = Path(path)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.stem}.", suffix=path.suffix)
    os.close(fd)
    try:
        fig.savefig(tmp, dpi=150)
        os.replace(tmp, path)
    finally:
        Path(tmp).unlink(missing_ok=True)
        plt.close(fig)
