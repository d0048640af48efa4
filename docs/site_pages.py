"""The parts of the site made from the build's outputs when the site is built (`conf.py`).

Nothing here is committed: each function writes a file under ``docs/_build/generated/``
that a page includes. They read what ``make`` wrote (``results/claims.json``,
``figures/``), the figure captions of the report (``workflow/report/<name>.rst``, rendered
as the workflow renders them, with the configuration of ``config/config.yaml``) and the
film that ships with the package.
"""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap
from pathlib import Path
from types import SimpleNamespace

import jinja2
import yaml

from turntable._atomic import write_text
from turntable._templates import markup, render
from turntable.claims.report import html_math, summary_line
from turntable.config import validate
from turntable.film import EXAMPLE_FILM

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "docs" / "_build" / "generated"
#: The templates of the generated parts.
TEMPLATES = ROOT / "docs" / "templates"
#: The arguments of ``turntable fit`` for `EXAMPLE_FILM` (its header gives the values).
EXAMPLE_FIT_ARGS = ["--radius", "0.005", "--rpm", "33.333333333333336"]


def _need(path: Path) -> Path:
    if not path.exists():
        raise SystemExit(f"{path.relative_to(ROOT)}: missing; run make before make docs")
    return path


def _write(name: str, text: str) -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    write_text(OUT / name, text)


def example_fit() -> None:
    """``example_fit.json``: what ``turntable fit`` prints for the film that ships."""
    command = [sys.executable, "-m", "turntable", "fit", str(EXAMPLE_FILM), *EXAMPLE_FIT_ARGS]
    out = subprocess.run(command, capture_output=True, text=True, check=True, cwd=ROOT)
    _write("example_fit.json", out.stdout)


def claims_table() -> None:
    """``claims.rst``: the counts, then one row a claim with its verdict.

    The table is HTML (template ``docs/templates/claims_table.html.j2``, escaped by
    Jinja2: a claim's text is shown as text), given to Sphinx as it is.
    """
    report = json.loads(_need(ROOT / "results" / "claims.json").read_text(encoding="utf-8"))
    table = render(
        "claims_table.html.j2",
        TEMPLATES,
        report=report,
        headings=("id", "where in the paper", "claim", "reproduced", "verdict"),
        math=lambda text: markup(html_math(str(text))),
    )
    summary = summary_line(report["summary"]).replace("`", "``")
    _write("claims.rst", f"{summary}\n\n.. raw:: html\n\n{textwrap.indent(table, '   ')}")


def gallery() -> None:
    """``gallery.rst``: the animation and Figures 1-10, each with the report's caption."""
    config = yaml.safe_load((ROOT / "config" / "config.yaml").read_text()) or {}
    problems = validate(config, ROOT / "workflow" / "schemas" / "config.schema.yaml")
    if problems:
        raise SystemExit("config/config.yaml: " + "; ".join(problems))
    context = SimpleNamespace(config=config)
    names = yaml.safe_load((ROOT / "workflow" / "figures.yaml").read_text())
    parts = []
    for name, image in [("animation", "animation.gif"), *((n, f"{n}.png") for n in names)]:
        caption = (ROOT / "workflow" / "report" / f"{name}.rst").read_text(encoding="utf-8")
        caption = jinja2.Template(caption).render(snakemake=context).strip()
        _need(ROOT / "figures" / image)
        title = name if name == "animation" else f"Figure {name[3:].split('_')[0]}"
        parts.append(
            f".. _{name}:\n\n{title}\n{'~' * len(title)}\n\n"
            f".. figure:: /../figures/{image}\n   :alt: {name}\n   :width: 100%\n\n"
            + "\n".join(f"   {line}" if line else "" for line in caption.splitlines())
            + "\n"
        )
    _write("gallery.rst", "\n".join(parts))


def _bibtex(kind: str, key: str, fields: dict) -> str:
    """A BibTeX entry, its values wrapped within 80 characters."""
    width = max(map(len, fields))
    lines = []
    for name, value in fields.items():
        head = f"  {name:<{width}} = {{"
        wrapped = textwrap.wrap(f"{value}}},", 80 - len(head))
        lines += [head + wrapped[0], *(" " * len(head) + w for w in wrapped[1:])]
    return f"@{kind}{{{key},\n" + "\n".join(lines) + "\n}\n"


def citation() -> None:
    """``citation.md``: the reproduced paper and this software, from ``CITATION.cff``."""
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))
    (paper,) = [r for r in cff["references"] if r["type"] == "article"]
    authors = " and ".join(f"{a['family-names']}, {a['given-names']}" for a in paper["authors"])
    initials = ", ".join(
        " ".join(f"{n[0]}." for n in a["given-names"].split()) + f" {a['family-names']}"
        for a in paper["authors"]
    )
    doi = paper["doi"]
    text = (
        "## The reproduced paper\n\n"
        f'{initials}, "{paper["title"]}", *{paper["journal"]}* {paper["volume"]}'
        f"({paper['issue']}), {paper['start']}–{paper['end']} ({paper['year']}), "
        f"DOI [{doi}](https://doi.org/{doi}).\n\n```bibtex\n"
        + _bibtex(
            "article",
            f"{paper['authors'][0]['family-names'].lower()}{paper['year']}",
            {
                "author": authors,
                "title": paper["title"],
                "journal": paper["journal"],
                "volume": paper["volume"],
                "number": paper["issue"],
                "pages": f"{paper['start']}--{paper['end']}",
                "year": paper["year"],
                "doi": doi,
            },
        )
        + "```\n\n## This reproduction\n\n```bibtex\n"
        + _bibtex(
            "software",
            "turntable",
            {
                "author": " and ".join(f"{{{a['name']}}}" for a in cff["authors"]),
                "title": cff["title"],
                "version": cff["version"],
                "year": cff["date-released"][:4],
                "license": cff["license"],
            },
        )
        + "```\n"
    )
    _write("citation.md", text)


def write_all() -> None:
    citation()
    example_fit()
    claims_table()
    gallery()
