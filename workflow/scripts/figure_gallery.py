"""One HTML page with the animation and every figure, each with its caption (results/figures.html).

Run by rule ``figure_gallery`` (workflow/rules/report.smk); the page is part of the HTML
report (category "Overview"), where otherwise a figure's caption shows only beside the
figure opened on its own. Captions are the report's own (workflow/report/<figure>.rst,
Jinja templates of the configuration, rendered as Snakemake renders them, then RST to HTML
with docutils, which stops at any warning); the PNGs are embedded, so the page is self-contained.
"""

import base64
import html
import logging
import os
from pathlib import Path
from types import SimpleNamespace

import jinja2
from docutils.core import publish_parts

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")
context = SimpleNamespace(config=snakemake.config)


def section(name: str, image: str, rst: str, mime: str) -> str:
    """One <figure>: the image embedded, then the caption rendered from its template."""
    text = jinja2.Template(Path(rst).read_text(encoding="utf-8")).render(snakemake=context)
    # A caption docutils cannot read (an undefined |substitution|, a broken role) stops the job.
    caption = publish_parts(text, writer="html", settings_overrides={"halt_level": 2})
    data = base64.b64encode(Path(image).read_bytes()).decode("ascii")
    return (
        f'<figure id="{name}"><img src="data:{mime};base64,{data}" alt="{name}">'
        f"<figcaption><b>{html.escape(name)}</b> (<code>{image}</code>, drawn by "
        f"<code>scripts/{name}.py</code>). {caption['body']}</figcaption></figure>"
    )


# The animation first (the report's viewer offers a GIF only as a download), then the figures.
sections = [
    section("animation", snakemake.input.animation, snakemake.input.animation_caption, "image/gif")
]
for name, png, rst in zip(
    snakemake.params.names, snakemake.input.pngs, snakemake.input.captions, strict=True
):
    sections.append(section(name, png, rst, "image/png"))
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
out = Path(snakemake.output[0])
tmp = out.with_name(f".{out.name}.partial")
tmp.write_text(page, encoding="utf-8")
os.replace(tmp, out)
logging.info("wrote %s with the animation and %d figures", out, len(sections) - 1)
