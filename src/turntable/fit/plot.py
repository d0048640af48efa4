"""Drawing a fit of ``turntable fit``: the data, both fitted paths and the residuals.

matplotlib is not a dependency of the package: it is imported by these functions only,
when ``turntable fit --plot`` (or a figure script) asks for a drawing.  Every number is
read from the JSON object of the command (`turntable.fit.result_json`), where a value that
is not finite, or a coefficient reported as a limit, is None: such a model is labelled
accordingly and, if it has no finite fit, left out of the drawing.
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from turntable._atomic import replacing
from turntable.film import Film
from turntable.fit.io import fitted_positions
from turntable.fit.models import COEFFICIENT, MODELS

#: Relative standard error above which a coefficient is written with its 95 % interval
#: instead of "value ± stderr" (which would suggest negative values).
INTERVAL_ABOVE = 0.3

#: Colour and label of each model.
STYLE = {
    "slipping": ("C0", "slipping"),
    "rolling_resistance": ("C3", "rolling resistance"),
}


def _two(x: float) -> str:
    """``x`` to two significant digits, without an exponent from 1e-3 to 1e5 (220, 0.046)."""
    rounded = float(f"{x:.2g}")
    return f"{rounded:g}" if 1e-3 <= abs(rounded) < 1e5 else f"{rounded:.2g}"


def value_with_error(
    value: float | None,
    stderr: float | None,
    ci95: Sequence[float | None] | None = None,
) -> str:
    """Return "value ± stderr" rounded to the second significant digit of stderr.

    With ``ci95`` and a relative error stderr / value above `INTERVAL_ABOVE`, return
    "value (95 %: low–high)" instead, the interval on the log scale of
    `turntable.fit` (exp(ln c -+ 1.96 se(ln c))).  None or non-finite parts are left out
    ("n/a" for a missing value).
    """
    if value is None or not math.isfinite(value):
        return "n/a"
    if stderr is None or not math.isfinite(stderr) or stderr <= 0:
        return f"{value:.4g}"
    if (
        ci95 is not None
        and value > 0
        and stderr / value > INTERVAL_ABOVE
        and all(v is not None and math.isfinite(v) for v in ci95)
    ):
        return f"{_two(value)} (95 %: {_two(ci95[0])}–{_two(ci95[1])})"
    decimals = max(0, 1 - math.floor(math.log10(stderr)))
    return f"{value:.{decimals}f} ± {stderr:.{decimals}f}"


def coefficient_text(entry: dict[str, Any], name: str) -> str:
    """Return the coefficient ``name`` of one model's JSON entry as text.

    "value ± stderr" or "value (95 %: low–high)" (`value_with_error`); for a coefficient
    at the end of its search range, the one-sided limit ("> 210" or "< 1e-05").
    """
    for kind, sign in (("lower", ">"), ("upper", "<")):
        limit = entry.get(f"{name}_{kind}_limit")
        if limit is not None:
            return f"{sign} {limit:.3g} (95 %)"
    return value_with_error(entry.get(name), entry.get(f"{name}_stderr"), entry.get(f"{name}_ci95"))


def _coefficient(result: dict[str, Any], model: str) -> str:
    name = COEFFICIENT[model]
    symbol = {"mu0": r"$\mu_0$", "delta": r"$\delta$"}[name]
    text = coefficient_text(result[model], name)
    return f"{symbol} {text}" if text[0] in "<>" else f"{symbol} = {text}"


def _drawable(result: dict[str, Any], model: str) -> bool:
    """Whether the JSON holds a finite fit of ``model`` to draw."""
    entry = result[model]
    return all(v is not None for v in entry.get("state0", [None])) and (
        entry.get(COEFFICIENT[model]) is not None
        or entry.get(f"{COEFFICIENT[model]}_search_bound") is not None
    )


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
    """Draw the tracked positions (mm) and the path of each fitted model on ``ax``.

    The selected model is drawn last, solid, over the other one, dashed: where the two
    paths coincide the selected one stays visible and the other shows through its gaps.
    """
    t = np.linspace(film.t[0], film.t[-1], max(n_curve, film.t.size))
    ax.plot(1e3 * film.x, 1e3 * film.y, ".", color="0.6", ms=1.5, label="data")
    selected = result.get("selected")
    for model in sorted(MODELS, key=lambda m: m == selected):
        if not _drawable(result, model):
            continue
        xy = fitted_positions(result, model, t)
        color, _ = STYLE[model]
        ax.plot(
            1e3 * xy[:, 0],
            1e3 * xy[:, 1],
            color=color,
            lw=0.8,
            ls="-" if selected in (None, model) else (0, (4, 2)),
            label=_label(result, model),
        )
    axis = result["setup"]["axis_m"]
    ax.plot(1e3 * axis[0], 1e3 * axis[1], "k+", ms=8, label="axis")
    ax.set(aspect="equal", xlabel="$x$ (mm)", ylabel="$y$ (mm)")


def draw_residuals(
    ax: Any, film: Film, result: dict[str, Any], windows: int = 100, coefficients: bool = False
) -> None:
    """Draw the residuals of each fit against time on ``ax``.

    Each frame's residual per coordinate, sqrt(|data - fit|^2 / 2) in mm, as faint
    points, and its rms over a moving window of 1/``windows`` of the film as a line: the
    fit of the right model stays flat at the tracking noise, a wrong one shows structure
    (the window holds at least 5 frames).
    The labels give each fit's rms residual and its model or, if ``coefficients``, its
    coefficient.
    """
    window = max(5, film.t.size // windows)
    for model in MODELS:
        if not _drawable(result, model):
            continue
        xy = fitted_positions(result, model, film.t)
        per_coordinate = np.hypot(film.x - xy[:, 0], film.y - xy[:, 1]) / math.sqrt(2.0)
        color, label = STYLE[model]
        rms = result[model]["rms_residual_m"]
        rms_text = "n/a" if rms is None else f"{1e3 * rms:.3g} mm"
        label = f"{label}, rms {rms_text}"
        if coefficients:
            label = f"{_coefficient(result, model)}\nrms {rms_text}"
        ax.semilogy(film.t, 1e3 * per_coordinate, ".", color=color, ms=1.0, alpha=0.25)
        ax.semilogy(
            film.t,
            1e3 * moving_rms(per_coordinate, window),
            color=color,
            lw=1.2,
            label=label,
        )
    ax.set(xlabel="$t$ (s)", ylabel="residual per coordinate (mm)")


def selection_text(result: dict[str, Any]) -> str:
    """Return the selection of a JSON result in words, e.g. "selected slipping (AICc
    difference 5.5e+03, Akaike weight 1)", marked "not decisive" where it is not."""
    sel = result["selection"]
    selected = result.get("selected")
    if selected is None:
        return "no model selected" + (f": {sel['reason']}" if sel.get("reason") else "")
    diff, weight = sel.get("aicc_difference"), sel.get("akaike_weights", {}).get(selected)
    parts = []
    if diff is not None:
        parts.append(f"AICc difference {diff:.3g}")
    if weight is not None:
        parts.append(f"Akaike weight {weight:.3g}")
    if not sel.get("decisive", True):
        parts.append("not decisive")
    return f"selected {STYLE[selected][1]}" + (f" ({', '.join(parts)})" if parts else "")


def plot_fit(path: str | os.PathLike[str], film: Film, result: dict[str, Any]) -> None:
    """Write a figure of the fit to ``path`` (format from its suffix), atomically.

    Left: the data and both fitted paths; right: the residuals against time.  The title
    names the selected model and the AICc difference (or why none is selected).  The file
    is readable by everyone (mode 0644, as `turntable.film.write_film` writes).
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax_p, ax_r) = plt.subplots(1, 2, figsize=(10.0, 4.6), layout="constrained")
    draw_paths(ax_p, film, result)
    draw_residuals(ax_r, film, result)
    ax_p.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.15), ncols=2)
    ax_r.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.15), ncols=2)
    fig.suptitle(f"{result['data']['file']}: {selection_text(result)}", fontsize=9)
    path = Path(path)
    try:
        with replacing(path) as tmp:
            fig.savefig(tmp, dpi=150)
    finally:
        plt.close(fig)
