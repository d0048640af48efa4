"""The page "What a film can tell" of the HTML report (results/film.html), from what the
camera of configuration section ``film`` can measure (Figure 8's measurability.json) and
what ``turntable fit`` recovered from the SYNTHETIC films (their JSON and their truth);
every number is read from those files.  Built by workflow/scripts/film_page.py.
"""

from __future__ import annotations

import html
import logging
import math

from turntable.fit.models import COEFFICIENT
from turntable.fit.plot import coefficient_text, selection_text

esc = html.escape


def g(x: float | None, digits: int = 3) -> str:
    """A number with ``digits`` significant digits ("n/a" for None)."""
    return "n/a" if x is None else f"{x:.{digits}g}"


def interval(entry: dict, name: str) -> str:
    """The 95 % interval of a fitted coefficient, to the decimal places of its value."""
    ci, se = entry.get(f"{name}_ci95"), entry.get(f"{name}_stderr")
    if not ci or None in ci or not se:
        return "&ndash;"
    places = max(0, 1 - math.floor(math.log10(se)))
    return f"{ci[0]:.{places}f} to {ci[1]:.{places}f}"


def film_page(measure: dict, truth: dict, fits: dict, figures: dict) -> str:
    """The page: ``measure`` (measurability.json), ``truth`` (synthetic.json), ``fits``
    (film name: its fit's JSON) and ``figures`` (figure name: its HTML) as read."""
    # what the camera can measure
    s = measure["setup"]
    table = measure["table"]
    rel = [se / m for se, m in zip(table["mu0_stderr"], table["mu0"], strict=True)]
    span = measure.get("reliable_mu0_range")
    limit = measure["indistinguishable_above_mu0"]
    camera = (
        f"a ball of radius {g(s['radius_m'])} m (k = {g(s['k'])}) on a turntable at "
        f"{g(s['omega_rad_s'])} rad/s, filmed at {g(s['fps'])} frames/s for {g(s['duration_s'])} s "
        f"with a tracking noise of {g(s['noise_m'])} m per coordinate"
    )
    if span is None:
        reach = "No value of the grid has a predicted relative error small enough to be reached."
    else:
        where = (
            f"for every &mu;<sub>0</sub> of the grid up to {g(span[1])}"
            if span[0] <= table["mu0"][0] * (1 + 1e-9)
            else f"for &mu;<sub>0</sub> from {g(span[0])} to {g(span[1])}"
        )
        reach = (
            f"Fits reach this bound where it is below {g(measure['reliable_relative_error'])}, "
            f"{where}; beyond, the fitted values scatter more than it predicts (dotted in "
            "Figure 8)."
        )
    told = (
        f"The slipping ball can be told from one rolling without slipping (AICc selects the "
        f"slipping model with probability at least {g(measure['selection_probability'])}) for "
        f"&mu;<sub>0</sub> below {g(limit)}; above, the two motions coincide to within the noise."
        if limit is not None
        else "The slipping ball can be told from one rolling without slipping over the whole grid."
    )
    step = max(1, len(table["mu0"]) // 10)
    rows = "".join(
        f"<tr><td>{g(m)}</td><td>{g(r, 2)}</td><td>{g(p, 3)}</td></tr>"
        for m, r, p in list(zip(table["mu0"], rel, table["selection_probability"], strict=True))[
            ::step
        ]
    )
    measurable = (
        "<h2>What the camera can measure</h2>"
        f"<p>For {camera}, the smallest standard error of &mu;<sub>0</sub> that a fit can reach is "
        "the Cram&eacute;r-Rao bound from the Fisher information of the exact solution, the "
        f"initial state unknown (<code>turntable.fit.predicted_stderr</code>). {reach} {told}</p>"
        "<table><tr><th>&mu;<sub>0</sub></th><th>predicted relative standard error of "
        "&mu;<sub>0</sub></th><th>probability that AICc selects slipping</th></tr>"
        f"{rows}</table>"
    )

    # the synthetic films
    SYMBOL = {"mu0": "&mu;<sub>0</sub>", "delta": "&delta;"}
    film_rows = []
    for name, spec in truth["films"].items():
        res = fits[name]
        model = spec["model"]
        coefficient = COEFFICIENT[model]
        entry = res[model]
        symbol, fitted = SYMBOL[coefficient], coefficient_text(entry, coefficient)
        if not res["data"]["synthetic"]:
            raise ValueError(f"{name}: the fit of a synthetic film is not marked synthetic")
        film_rows.append(
            "<tr>"
            f"<td><b>{esc(name)}</b> (SYNTHETIC)</td>"
            f"<td>{esc(model.replace('_', ' '))}, {symbol} = {g(spec['coefficient'])}</td>"
            f"<td>{symbol}{' ' if fitted[0] in '<>' else ' = '}{esc(fitted)}</td>"
            f"<td>{interval(entry, coefficient)}</td>"
            f"<td>{g(1e3 * entry['rms_residual_m'])} mm</td>"
            f"<td>{g(entry['residual_lag1_autocorrelation'], 2)} "
            f"(&plusmn;{g(entry['residual_lag1_white_sd'], 2)})</td>"
            f"<td>{esc(selection_text(res))}</td>"
            f"<td>{esc('; '.join(res['warnings'])) or 'none'}</td>"
            "</tr>"
        )
    first = next(iter(truth["films"]))
    data = fits[first]["data"]
    films = (
        "<h2>Synthetic films, fitted (SYNTHETIC data)</h2>"
        f"<p>{esc(truth['note'])}. Each film ({data['n_frames']} frames over "
        f"{g(data['duration_s'])} s, {g(data['turntable_turns'])} turns of the turntable) was "
        "fitted by <code>turntable fit</code> with both models; the table gives, for the model "
        "the film was made with, the truth, the fitted coefficient with its standard error (or "
        "its 95 % interval when that error is large), the 95 % interval on the log scale, the rms "
        "residual (the tracking noise when the model fits), the lag-1 autocorrelation of the "
        "residuals with its spread for white noise, then the selection with its evidence and "
        "the warnings of the command.</p>"
        "<table><tr><th>film</th><th>truth</th><th>fitted</th><th>95 % interval</th>"
        "<th>rms residual</th><th>residual lag-1 autocorrelation</th><th>selection</th>"
        f"<th>warnings</th></tr>{''.join(film_rows)}</table>"
    )

    page = (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        "<title>What a film can tell</title>"
        "<style>body{font-family:sans-serif;font-size:14px;max-width:60em;margin:auto}"
        "img{max-width:100%;display:block;margin:auto}figure{margin:2em 0}"
        "figcaption p{display:inline}table{border-collapse:collapse;margin:1em 0}"
        "td,th{border:1px solid #ccc;padding:0.2em 0.5em;vertical-align:top}</style>"
        "</head><body>\n<h1>What a film can tell</h1>\n"
        "<p>A ball filmed on a turntable gives, through <code>turntable fit</code>, its friction "
        "coefficient and the mechanism that explains its motion. Below: what a given camera can "
        "measure at all, then the synthetic films of the pipeline fitted like a real film.</p>\n"
        + measurable
        + figures.get("fig8_measurability", "")
        + films
        + figures.get("fig9_fit", "")
        + "\n</body></html>\n"
    )
    if not all(math.isfinite(x) for x in rel):
        logging.warning("non-finite predicted errors of mu0 in the measurability")
    return page
