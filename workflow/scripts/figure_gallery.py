"""One HTML page with the animation and every figure, each with its caption (results/figures.html).

Run by rule ``figure_gallery`` (workflow/rules/report.smk); the page is part of the HTML
report (category "Overview"), where otherwise a figure's caption shows only beside the
figure opened on its own. Each figure is drawn with its caption by
workflow/scripts/report_figure.py, embedded, so the page is self-contained.
"""

import logging

from report_figure import figure_html

from turntable._atomic import write_text

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
page = (
    '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>Figures</title>'
    "<style>body{font-family:sans-serif;font-size:14px;max-width:60em;margin:auto}"
    "img{max-width:100%;display:block;margin:auto}figure{margin:2em 0;border-bottom:1px solid #ccc}"
    "figcaption p{display:inline}</style></head><body>\n<h1>Figures of the reproduction</h1>\n"
    "<p>The animation of the ball, then every figure of the reproduction with its caption, "
    "numbered as its file name (figN), as in the article and the README. Figures of the "
    "original paper are named as the paper's (e.g. the paper's Fig. 4).</p>\n"
    + "\n".join(sections)
    + "\n</body></html>\n"
)
out = snakemake.output[0]
write_text(out, page)
logging.info("wrote %s with the animation and %d figures", out, len(sections) - 1)
