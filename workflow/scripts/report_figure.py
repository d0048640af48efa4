"""One figure of an HTML page of the report, with its caption (shared by the report's pages).

Imported by workflow/scripts/figure_gallery.py and workflow/scripts/film_page.py (Snakemake
puts the folder of a rule's script on the import path); both rules list this file in their
input ``code``, so that editing it rebuilds both
pages. Captions are the report's own
(workflow/report/<figure>.rst, Jinja templates of the configuration, rendered as Snakemake
renders them, then RST to HTML with docutils, which stops at any warning); the image is
embedded, so a page is self-contained.
"""

import base64
from pathlib import Path
from types import SimpleNamespace

import jinja2
from docutils.core import publish_parts

from turntable._templates import markup, render

#: The templates of the report's pages (``figure.html.j2``, ``figures.html.j2``).
TEMPLATES = Path(__file__).resolve().parents[1] / "templates"


def figure_html(name: str, image: str, rst: str, mime: str, config: dict) -> str:
    """One <figure>: the image ``image`` embedded, then the caption rendered from ``rst``.

    Template ``workflow/templates/figure.html.j2``, escaped by Jinja2 (the id, the name and
    the path of the image are text); the caption is docutils' HTML, inserted as it is.
    """
    context = SimpleNamespace(config=config)
    text = jinja2.Template(Path(rst).read_text(encoding="utf-8")).render(snakemake=context)
    # A caption docutils cannot read (an undefined |substitution|, a broken role) stops the job.
    caption = publish_parts(text, writer="html", settings_overrides={"halt_level": 2})
    data = base64.b64encode(Path(image).read_bytes()).decode("ascii")
    return markup(
        render(
            "figure.html.j2",
            TEMPLATES,
            name=name,
            image=image,
            mime=mime,
            data=data,
            caption=markup(caption["body"]),
        )
    )
