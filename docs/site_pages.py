"""The parts of the site made from the build's outputs when the site is built (`conf.py`).

Nothing here is committed: each function writes a file under ``docs/_build/generated/``
that a page includes, or the notebooks under ``docs/notebooks/``. They read what ``make``
and ``make notebooks`` wrote (``results/claims.json``, ``figures/``,
``results/notebooks/``), the figure captions of the report (``workflow/report/<name>.rst``,
rendered as the workflow renders them, with the configuration of ``config/config.yaml``),
``pyproject.toml`` and the film that ships with the package.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
import textwrap
import tomllib
from pathlib import Path
from types import SimpleNamespace

import jinja2
import yaml

from turntable._atomic import write_text
from turntable._templates import markup, render
from turntable.claims.report import decisive_lines, html_math, summary_line
from turntable.config import validate
from turntable.film import EXAMPLE_FILM

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "docs" / "_build" / "generated"
#: The executed notebooks of ``make notebooks``, and where the site takes them from.
NOTEBOOKS = ROOT / "results" / "notebooks"
SITE_NOTEBOOKS = ROOT / "docs" / "notebooks"
#: The templates of the generated parts.
TEMPLATES = ROOT / "docs" / "templates"
#: The arguments of ``turntable fit`` for `EXAMPLE_FILM` (its header gives the values).
EXAMPLE_FIT_ARGS = ["--radius", "0.005", "--rpm", "33.3333333"]
#: A number written with more digits than a page shows.
_LONG_FLOAT = re.compile(r"(?<![\w.])-?\d+\.\d*(?:e[-+]?\d+)?(?![\w.])", re.IGNORECASE)


def round_floats(text: str, digits: int = 4) -> str:
    """``text`` with each number of more than ``digits`` significant digits rounded to them
    (``0.6666666666666666`` to ``0.6667``, ``10309.818`` to ``10310``); integers and short
    numbers are left alone."""

    def rounded(match: re.Match) -> str:
        number = match.group()
        mantissa = re.split("[eE]", number)[0].lstrip("-").replace(".", "").lstrip("0")
        if len(mantissa) <= digits:
            return number
        value = float(number)
        return str(round(value)) if abs(value) >= 10**digits else f"{value:.{digits}g}"

    return _LONG_FLOAT.sub(rounded, text)


def _need(path: Path, command: str = "make") -> Path:
    if not path.exists():
        shown = path.relative_to(ROOT) if path.is_relative_to(ROOT) else path
        raise SystemExit(f"{shown}: missing; run {command} before make docs")
    return path


def _write(name: str, text: str) -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    write_text(OUT / name, text)


def example_fit() -> None:
    """``example_fit.json``: what ``turntable fit`` prints for the film that ships."""
    command = [sys.executable, "-m", "turntable", "fit", str(EXAMPLE_FILM), *EXAMPLE_FIT_ARGS]
    out = subprocess.run(command, capture_output=True, text=True, check=True, cwd=ROOT)
    _write("example_fit.json", round_floats(out.stdout))


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
        math=lambda text: markup(html_math(round_floats(str(text)))),
    )
    summary = summary_line(report["summary"]).replace("`", "``")
    _write("claims.rst", f"{summary}\n\n.. raw:: html\n\n{textwrap.indent(table, '   ')}")


#: The claims whose line of ``turntable claims`` the claims guide shows.
EXAMPLE_CLAIMS = ("model.reduction", "solution.centre")


def claims_lines() -> None:
    """``claims_lines.txt``: the lines of ``turntable claims`` for `EXAMPLE_CLAIMS`, their
    columns aligned among themselves."""
    report = json.loads(_need(ROOT / "results" / "claims.json").read_text(encoding="utf-8"))
    rows = [line.split(maxsplit=2) for line in decisive_lines(report)]
    rows = [row for row in rows if row[0] in EXAMPLE_CLAIMS]
    widths = [max(len(row[i]) for row in rows) for i in (0, 1)]
    text = "".join(f"{a:<{widths[0]}}  {b:<{widths[1]}}  {c}\n" for a, b, c in rows)
    _write("claims_lines.txt", round_floats(text))


def _title(name: str) -> str:
    """``Figure 4`` for ``fig4_trajectories``, ``animation`` for itself."""
    return "Animation" if name == "animation" else f"Figure {name[3:].split('_')[0]}"


def notebooks() -> None:
    """``docs/notebooks/<name>.ipynb``: each notebook of ``make notebooks`` as it ran (not run
    again), under a title that names its script; ``notebooks.rst``, their table of contents,
    the figures' first in the order of the article."""
    figures = ["animation", *yaml.safe_load((ROOT / "workflow" / "figures.yaml").read_text())]
    scripts = sorted((p.stem for p in (ROOT / "scripts").glob("*.py")), key=len, reverse=True)
    shutil.rmtree(SITE_NOTEBOOKS, ignore_errors=True)
    SITE_NOTEBOOKS.mkdir()
    for path in sorted(NOTEBOOKS.glob("*.ipynb")):
        name = path.stem
        script = next(s for s in scripts if name == s or name.startswith(f"{s}_"))
        notebook = json.loads(path.read_text(encoding="utf-8"))
        wildcards = name.removeprefix(script).lstrip("_")
        title = f"{_title(name)}: notebook" if name in figures else script
        title += f" ({round_floats(wildcards)})" if wildcards else ""
        text = [
            f"# {title}\n\n",
            f"`scripts/{script}.py` ({{download}}`download </../scripts/{script}.py>`) as "
            "`make notebooks` ran it, with its outputs",
        ]
        text.append(f" ({{ref}}`the figure <{name}>`).\n" if name in figures else ".\n")
        cell = {"cell_type": "markdown", "id": "site-title", "metadata": {}, "source": text}
        notebook["cells"].insert(0, cell)
        (SITE_NOTEBOOKS / path.name).write_text(json.dumps(notebook), encoding="utf-8")
    names = sorted(p.stem for p in SITE_NOTEBOOKS.glob("*.ipynb"))
    for name in figures:
        _need(NOTEBOOKS / f"{name}.ipynb", "make notebooks")
    order = [*figures, *(n for n in names if n not in figures)]
    entries = "".join(f"   /notebooks/{name}\n" for name in order)
    _write("notebooks.rst", f".. toctree::\n   :maxdepth: 1\n\n{entries}")


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
        caption = round_floats(jinja2.Template(caption).render(snakemake=context).strip())
        _need(ROOT / "figures" / image)
        title = _title(name)
        parts.append(
            f".. _{name}:\n\n{title}\n{'~' * len(title)}\n\n"
            f".. figure:: /../figures/{image}\n   :alt: {name}\n   :width: 100%\n\n"
            + "\n".join(f"   {line}" if line else "" for line in caption.splitlines())
            + f"\n\n:doc:`Notebook </notebooks/{name}>` · "
            f":download:`scripts/{name}.py </../scripts/{name}.py>`\n"
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


def installation() -> None:
    """``installation.md``: the wheel's name, the dependencies and each extra, from
    ``pyproject.toml``."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    wheel = f"turntable-{project['version']}-py3-none-any.whl"

    def names(requirements: list[str]) -> str:
        return ", ".join(requirements) or "nothing more"

    rows = "".join(
        f"| {extra} | {names(packages)} |\n"
        for extra, packages in project["optional-dependencies"].items()
    )
    _write(
        "installation.md",
        f"```sh\npip wheel --no-deps --wheel-dir dist .\n"
        f"pip install dist/{wheel}\n```\n\n"
        f"It installs {names(project['dependencies'])}. An extra adds the packages of a "
        'part of the project, for example `pip install ".[video]"`:\n\n'
        f"| extra | adds |\n|---|---|\n{rows}",
    )


def write_all() -> None:
    installation()
    citation()
    example_fit()
    claims_table()
    claims_lines()
    notebooks()
    gallery()
