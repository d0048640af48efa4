"""One HTML page with the animation and every figure, each with its caption (results/figures.html).

Run by rule ``figure_gallery`` (workflow/rules/report.smk); the page is part of the HTML
report (category "Overview"), where otherwise a figure's caption shows only beside the
figure opened on its own. Each figure is drawn with its caption by
workflow/scripts/report_figure.py, embedded, so the page is self-contained.
"""

import logging

from report_figure import TEMPLATES, figure_html

from turntable._atomic import write_text
from turntable._templates import render

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")


# The animation first (the report's viewer offers a GIF only as a download), then the figures.
sections = [
    figure_html(
        "animation",
        snakemake.input.animation,
        snakemake.input.animation_caption,
        "image/gif",
        snakemake.config,
    )
]
for name, png, rst in zip(
    snakemake.params.names, snakemake.input.pngs, snakemake.input.captions, strict=True
):
    sections.append(figure_html(name, png, rst, "image/png", snakemake.config))
page = render("figures.html.j2", TEMPLATES, figures=sections)
out = snakemake.output[0]
write_text(out, page)
logging.info("wrote %s with the animation and %d figures", out, len(sections) - 1)
