"""The page "What a film can tell" of the HTML report (results/film.html), built by
`turntable.fit._page` from the measurability of Figure 8 and the fits of the SYNTHETIC films,
with Figures 8 and 9 and their captions (workflow/scripts/report_figure.py). Run by rule
``film_page`` (workflow/rules/film.smk).
"""

import json
import logging
from pathlib import Path

from report_figure import figure_html

from turntable._atomic import write_text
from turntable.fit._page import film_page

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")


def read(path):
    return json.loads(Path(path).read_text(encoding="utf-8"))


fits = {Path(p).stem: read(p) for p in snakemake.input.fits}
figures = {
    name: figure_html(name, png, rst, "image/png", snakemake.config)
    for name, png, rst in zip(
        snakemake.params.names, snakemake.input.pngs, snakemake.input.captions, strict=True
    )
}
page = film_page(read(snakemake.input.measurability), read(snakemake.input.truth), fits, figures)
out = snakemake.output[0]
write_text(out, page)
logging.info("wrote %s: %d films", out, len(fits))
