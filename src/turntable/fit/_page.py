"""The page "What a film can tell" of the HTML report (results/film.html), from what the
camera of configuration section ``film`` can measure (Figure 8's measurability.json) and
what ``turntable fit`` recovered from the SYNTHETIC films (their JSON and their truth);
every number is read from those files.  Built by workflow/scripts/film_page.py.
"""

from __future__ import annotations

import logging
import math

from turntable._templates import markup, render
from turntable.fit.models import COEFFICIENT
from turntable.fit.plot import coefficient_text, selection_text

#: The HTML of each coefficient's symbol.
SYMBOL = {"mu0": "&mu;<sub>0</sub>", "delta": "&delta;"}


def g(x: float | None, digits: int = 3) -> str:
    """A number with ``digits`` significant digits ("n/a" for None)."""
    return "n/a" if x is None else f"{x:.{digits}g}"


def interval(entry: dict, name: str) -> str | None:
    """The 95 % interval of a fitted coefficient, to the decimal places of its value (None
    where the fit gives none)."""
    ci, se = entry.get(f"{name}_ci95"), entry.get(f"{name}_stderr")
    if not ci or None in ci or not se:
        return None
    places = max(0, 1 - math.floor(math.log10(se)))
    return f"{ci[0]:.{places}f} to {ci[1]:.{places}f}"


def film_page(measure: dict, truth: dict, fits: dict, figures: dict) -> str:
    """The page (template ``turntable/templates/film.html.j2``, escaped by Jinja2).

    Parameters
    ----------
    measure : dict
        Figure 8's ``measurability.json``, as read.
    truth : dict
        ``synthetic.json``, the truth of the SYNTHETIC films, as read.
    fits : dict
        Film name: the JSON of its fit (``turntable fit``), as read.
    figures : dict
        Figure name: its HTML (a figure with its caption), inserted as it is.

    Returns
    -------
    str
        The page: what the camera can measure, then the fitted films.
    """
    table = measure["table"]
    rel = [se / m for se, m in zip(table["mu0_stderr"], table["mu0"], strict=True)]
    span = measure.get("reliable_mu0_range")
    step = max(1, len(table["mu0"]) // 10)
    films = []
    for name, spec in truth["films"].items():
        res = fits[name]
        if not res["data"]["synthetic"]:
            raise ValueError(f"{name}: the fit of a synthetic film is not marked synthetic")
        model = spec["model"]
        coefficient = COEFFICIENT[model]
        entry = res[model]
        films.append(
            {
                "name": name,
                "model": model.replace("_", " "),
                "symbol": markup(SYMBOL[coefficient]),
                "truth": spec["coefficient"],
                "fitted": coefficient_text(entry, coefficient),
                "interval": interval(entry, coefficient),
                "entry": entry,
                "selection": selection_text(res),
                "warnings": res["warnings"],
            }
        )
    page = render(
        "film.html.j2",
        setup=measure["setup"],
        measure=measure,
        span=span,
        span_from_start=span is not None and span[0] <= table["mu0"][0] * (1 + 1e-9),
        limit=measure["indistinguishable_above_mu0"],
        grid=list(zip(table["mu0"], rel, table["selection_probability"], strict=True))[::step],
        truth=truth,
        data=fits[next(iter(truth["films"]))]["data"],
        films=films,
        figures={name: markup(html) for name, html in figures.items()},
        g=g,
    )
    if not all(math.isfinite(x) for x in rel):
        logging.warning("non-finite predicted errors of mu0 in the measurability")
    return page
