"""Machine- and human-readable reports of the claims registry.

``results/claims.json`` holds everything (package version, git commit,
parameters, every field of every claim); ``results/claims.md`` is a table a
person reads.  Both are deterministic: keys are sorted, floats are rounded to
12 significant digits, and no time stamp is written.
"""

from __future__ import annotations

import json
import re
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import turntable
from turntable import reference
from turntable._atomic import write_text
from turntable.claims import VERDICTS, evaluate_all, resolve_params
from turntable.claims._core import clean, split_bound

#: What each verdict means, in the words of the report (docs/verdicts.md and the article agree).
VERDICT_MEANINGS: dict[str, str] = {
    "confirmed": "the claim holds as stated",
    "refined": "it holds in a narrower or more precise form, stated in the evidence",
    "corrected": (
        "a formula the paper prints is wrong; the evidence states the right one (an erratum)"
    ),
    "undecidable": ("whether it holds depends on values the paper does not give; never confirmed"),
    "failed": "the numbers contradict it",
}

#: Version of the layout of ``claims.json`` (2: each claim names its ``decisive`` value).
SCHEMA_VERSION = 2


#: The two sources of a claim: the paper's statements and the reproduction's additions.
SOURCES: dict[str, str] = {"paper": "of the paper", "project": "added by the reproduction"}


def summarize(records: list[Mapping[str, Any]]) -> dict[str, Any]:
    """Count the records per verdict, per source and per verdict within each source.

    Returns
    -------
    dict
        ``<verdict>`` (count over all records, for each of `VERDICTS`), ``total``,
        ``paper`` and ``project`` (count per source), ``by_source`` (source -> verdict ->
        count: the paper's claims counted apart from the reproduction's additions),
        ``verdicts`` (the verdicts from best to worst) and ``ids`` (verdict -> ids).
    """
    counts: dict[str, Any] = {v: sum(r["verdict"] == v for r in records) for v in VERDICTS}
    counts["total"] = len(records)
    for source in SOURCES:
        counts[source] = sum(r["source"] == source for r in records)
    counts["by_source"] = {
        source: {
            v: sum(r["source"] == source and r["verdict"] == v for r in records) for v in VERDICTS
        }
        for source in SOURCES
    }
    counts["verdicts"] = list(VERDICTS)
    counts["ids"] = {v: [r["id"] for r in records if r["verdict"] == v] for v in VERDICTS}
    return counts


def build_report(
    params: Mapping[str, Any] | None = None,
    *,
    commit: str = "unknown",
    provenance: Mapping[str, Any] | None = None,
) -> dict[str, Any]:
    """Evaluate every claim and assemble the report.

    Parameters
    ----------
    params : mapping, optional
        Check parameters (the ``claims:`` section of the configuration).
    commit : str
        Git commit of the code that produced the report.
    provenance : mapping, optional
        The record of :func:`turntable.provenance.provenance` (commit, dirty tree, Python
        and library versions), stored under ``provenance``.

    Returns
    -------
    dict
        ``schema, package, version, git_commit, provenance, params, reference_digits
        (the working precision of the high-precision references, `turntable.reference`),
        order, summary (count per verdict), claims`` (records keyed by id).
    """
    p = resolve_params(params)
    records = evaluate_all(p)
    counts = summarize(records)
    return clean(
        {
            "schema": SCHEMA_VERSION,
            "package": "turntable",
            "version": turntable.__version__,
            "git_commit": commit,
            "provenance": dict(provenance) if provenance is not None else None,
            "params": p,
            "reference_digits": {
                "eigenvalues": reference.DPS,
                "characteristic_roots": reference.ROOTS_DPS,
                "rolling": reference.rolling.DPS,
            },
            "order": [r["id"] for r in records],
            "summary": counts,
            "claims": {r["id"]: r for r in records},
        }
    )


def to_json(report: Mapping[str, Any]) -> str:
    """Serialise a report deterministically (sorted keys, two-space indent, final newline)."""
    return json.dumps(report, indent=2, sort_keys=True, ensure_ascii=False, allow_nan=False) + "\n"


def _cell(text: Any) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _paper_value(value: Mapping[str, Any] | None) -> str:
    if not value:
        return "-"
    return str(value.get("text", "-"))


def summary_line(summary: Mapping[str, Any]) -> str:
    """Return the counts of a report in words, naming every claim that is not confirmed.

    The paper's claims are counted apart from the reproduction's additions, every verdict
    of the paper's claims is counted (also when 0), and the ids of corrected, undecidable
    and failed claims are named, so that a count of 0 failed never hides an erratum.
    """
    paper = summary["by_source"]["paper"]
    added = summary["by_source"]["project"]
    text = (
        f"{summary['total']} claims. Of the {summary['paper']} {SOURCES['paper']}: "
        + ", ".join(f"{paper[v]} {v}" for v in VERDICTS)
        + f"; of the {summary['project']} {SOURCES['project']}: "
        + (", ".join(f"{added[v]} {v}" for v in VERDICTS if added[v]) or "none")
        + "."
    )
    for v in ("corrected", "undecidable", "failed"):
        if summary["ids"][v]:
            text += f" {v.capitalize()}: " + ", ".join(f"`{i}`" for i in summary["ids"][v]) + "."
    return text


def _bound_text(bound: Any) -> str:
    relation, limit = split_bound(bound)
    return f"{relation} {limit}"


def values_and_bounds(claim: Mapping[str, Any]) -> str:
    """Return ``key = value (bound)`` for every reproduced value that has a tolerance."""
    return "; ".join(
        f"`{key}` = {claim['reproduced'][key]} ({_bound_text(bound)})"
        for key, bound in claim["tolerance"].items()
    )


def decisive_value(claim: Mapping[str, Any]) -> str:
    """Return ``key = value (bound)`` for the reproduced value that decides the verdict.

    A check that did not reach its expected verdict may leave that value unbounded:
    ``(no bound: expected <verdict>)`` then.
    """
    key = claim["decisive"]
    bound = claim["tolerance"].get(key)
    text = f"no bound: expected {claim['expected']}" if bound is None else _bound_text(bound)
    return f"{key} = {claim['reproduced'][key]} ({text})"


def decisive_lines(report: Mapping[str, Any]) -> list[str]:
    """Return one line per claim, in the report's order: id, verdict, deciding value.

    Parameters
    ----------
    report : mapping
        A claims report (`build_report`, or ``results/claims.json`` read back).

    Returns
    -------
    list of str
        ``<id>  <verdict>  <key> = <value> (<relation> <bound>)``, the columns aligned;
        the key is the claim's ``decisive`` (`turntable.claims.register`) and value and
        bound are those of ``reproduced`` and ``tolerance``, as the JSON holds them.
    """
    order = list(report["order"])
    width = max((len(cid) for cid in order), default=0)
    verdict_width = max(len(v) for v in VERDICTS)
    return [
        f"{cid:<{width}}  {report['claims'][cid]['verdict']:<{verdict_width}}  "
        + decisive_value(report["claims"][cid])
        for cid in order
    ]


def to_markdown(report: Mapping[str, Any]) -> str:
    """Render a report as a Markdown document with one table row per claim."""
    lines = [
        "# Claims of Ivanova (2019) and their reproduction",
        "",
        f"turntable {report['version']}, commit `{report['git_commit']}`. "
        + summary_line(report["summary"]),
        "",
        "Verdicts: "
        + "; ".join(f"**{v}**: {VERDICT_MEANINGS[v]}" for v in VERDICTS)
        + ". Claims added by the reproduction (not the paper's) are marked *(addition)*; "
        "their location says what in the paper they build on.",
        "",
        "| id | where in the paper | claim | paper's value | reproduced | verdict |",
        "|---|---|---|---|---|---|",
    ]
    for cid in report["order"]:
        c = report["claims"][cid]
        lines.append(
            "| "
            + " | ".join(
                _cell(x)
                for x in (
                    f"`{cid}`" + (" *(addition)*" if c["source"] == "project" else ""),
                    c["where"]["label"],
                    c["claim"],
                    _paper_value(c["paper_value"]),
                    c["summary"],
                    f"**{c['verdict']}**",
                )
            )
            + " |"
        )
    lines += ["", "## Evidence", ""]
    for cid in report["order"]:
        c = report["claims"][cid]
        lines.append(
            f"- `{cid}` ({c['verdict']}; decided by {_cell(decisive_value(c))}): "
            f"{_cell(c['evidence'])}"
        )
    lines += ["", "## Reproduced values and their bounds", ""]
    for cid in report["order"]:
        c = report["claims"][cid]
        lines.append(f"- `{cid}`: {_cell(values_and_bounds(c))}")
    lines += ["", "## Methods", ""]
    for cid in report["order"]:
        c = report["claims"][cid]
        lines.append(f"- `{cid}`: {_cell(c['method'])}")
    return "\n".join(lines) + "\n"


_GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "eps": "ε", "lambda": "λ",
    "mu": "μ", "nu": "ν", "pi": "π", "rho": "ρ", "sigma": "σ", "phi": "φ", "omega": "ω",
    "Omega": "Ω", "infinity": "∞",
}  # fmt: skip
#: "~=" is "approximately" (≈), "~" "of the order of" or "behaves like" (∼).
_SYMBOLS = {
    "<=": "≤", ">=": "≥", "->": "→", "+-": "±", "-+": "∓", "!=": "≠", "~=": "≈", "~": "∼",
}  # fmt: skip
#: One token of the registry's plain-text mathematics (the same forms as the article's
#: ascii-math rule in paper/values.typ): exp(2 pi), 6.9e-25, ^-2 and ^(3/2), x0, u0 and mu0*,
#: alpha1, sigma_g, lambda_{1,2} and lambda_+, vx and wy, the angular velocity w (with an index or a
#: subscript: w1, w_h), the cross product "gamma x", z+ and z-, sqrt, the symbols, and a
#: minus between spaces.
_MATH_TOKEN = re.compile(
    r"exp\(2 pi\)"
    r"|\bgamma x\b"
    r"|\b\d(?:\.\d+)?e[-+]?\d+\b"
    r"|\^(?:\([^()]*\)|[-+]?\d+(?:\.\d+)?)"
    r"|(?<![\w.])(?:" + "|".join(sorted(_GREEK, key=len, reverse=True)) + r")\d*"
    r"(?:_(?:c|g|h|dim)\b|_\{[^}]*\}|_[+-])?\*?(?![\w.])"
    r"|(?<![\w.])[xyzru]0\*?(?![\w.])"
    r"|(?<![\w.])[vw][xyz](?![\w.])"
    r"|(?<![\w.])w(?:\d+|_(?:c|g|h)\b|_\{[^}]*\})?(?!\w|\.\w)"
    r"|(?<![\w.])z[+-](?=[\s,.;:)|]|$)"
    r"|\bsqrt\(|<=|>=|->|\+-|-\+|!=|~=|~| - "
)


def _minus(text: str) -> str:
    return text.replace("-", "\u2212")


def _math_html(token: str) -> str:
    """HTML of one token of `_MATH_TOKEN` (letters, subscripts, superscripts)."""
    from html import escape

    if token == "exp(2 pi)":
        return "e<sup>2π</sup>"
    if token == "gamma x":
        return "γ ×"
    if token == " - ":
        return " \u2212 "
    if token == "sqrt(":
        return "√("
    if token in _SYMBOLS:
        return _SYMBOLS[token]
    if token.startswith("^"):
        power = token[1:].strip("()").replace(" ", "")
        power = re.sub(r"[A-Za-z]+", lambda m: _GREEK.get(m[0], m[0]), power)
        return f"<sup>{escape(_minus(power))}</sup>"
    if re.fullmatch(r"\d(?:\.\d+)?e[-+]?\d+", token):
        mantissa, exponent = token.split("e")
        power = f"10<sup>{_minus(str(int(exponent)))}</sup>"
        return power if mantissa == "1" else f"{mantissa}×{power}"
    if re.fullmatch(r"z[+-]", token):
        return f"z<sub>{_minus(token[1])}</sub>"
    if re.fullmatch(r"[vw][xyz]", token):
        return f"{'ω' if token[0] == 'w' else 'v'}<sub>{token[1]}</sub>"
    m = re.fullmatch(r"([A-Za-z]+)(\d*)(?:_(c|g|h|dim|\{[^}]*\}|[+-]))?(\*?)", token)
    assert m is not None, token
    name, digits, sub, star = m.groups()
    out = "ω" if name == "w" else _GREEK.get(name, name)
    if digits:
        out += f"<sub>{digits}</sub>"
    if sub:
        sub = _minus(sub.strip("{}"))
        out += f"<sup>{sub}</sup>" if sub == "dim" else f"<sub>{sub}</sub>"
    return out + ("<sup>*</sup>" if star else "")


def html_math(text: str) -> str:
    """Escape ``text`` for HTML and typeset its plain-text mathematics.

    The registry writes mathematics in plain text (``mu0^-2``, ``exp(2 pi)``,
    ``|alpha2|/beta``, ``x0``, ``<=``, ``~=``); here Greek names (and the angular
    velocity w) become letters, indices
    subscripts, powers superscripts and ``1e-06`` becomes 10<sup>−6</sup>. Words that
    are not mathematics, and identifiers such as ``spectrum.alpha1_peak``, are left as
    they are.

    Examples
    --------
    >>> html_math("N > exp(2 pi) ~= 535.5 for mu0 -> 0")
    'N &gt; e<sup>2π</sup> ≈ 535.5 for μ<sub>0</sub> → 0'
    """
    from html import escape

    out, last = [], 0
    for m in _MATH_TOKEN.finditer(text):
        out += [escape(text[last : m.start()]), _math_html(m[0])]
        last = m.end()
    out.append(escape(text[last:]))
    return "".join(out)


def _code_ids(text: str) -> str:
    """HTML: the `id` spans of a summary line as <code> elements."""
    return re.sub(r"`([^`]+)`", r"<code>\1</code>", text)


_VERDICT_COLOURS = {
    "confirmed": "#1b7837",
    "refined": "#b35806",
    "corrected": "#8c510a",
    "undecidable": "#5e3c99",
    "failed": "#b2182b",
}


def to_html(report: Mapping[str, Any]) -> str:
    """Render a report as a self-contained HTML page: the counts, the table of claims, then
    the evidence of each verdict with the value that decides it.

    The columns are those of :func:`to_markdown`; the verdict is coloured. Shown in the
    HTML report of the workflow (rule ``claims_table``).
    """
    from html import escape

    rows = []
    for cid in report["order"]:
        c = report["claims"][cid]
        colour = _VERDICT_COLOURS.get(c["verdict"], "#000000")
        cells = (
            f"<code>{escape(cid)}</code>"
            + (" <i>(addition)</i>" if c["source"] == "project" else ""),
            escape(str(c["where"]["label"])),
            html_math(str(c["claim"])),
            html_math(_paper_value(c["paper_value"])),
            html_math(str(c["summary"])),
            f'<b style="color:{colour}">{escape(c["verdict"])}</b>',
        )
        rows.append("<tr>" + "".join(f"<td>{x}</td>" for x in cells) + "</tr>")
    head = "".join(
        f"<th>{h}</th>"
        for h in ("id", "where in the paper", "claim", "paper's value", "reproduced", "verdict")
    )
    # why each verdict is what it is, and the value that decides it (as in claims.md)
    evidence = [
        f"<li><code>{escape(cid)}</code> ({escape(c['verdict'])}"
        + (
            f"; decided by <code>{escape(decisive_value(c))}</code>"
            if c.get("decisive") is not None
            else ""
        )
        + f"): {html_math(str(c['evidence']))}</li>"
        for cid in report["order"]
        if "evidence" in (c := report["claims"][cid])
    ]
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        "<title>Claims of Ivanova (2019) and their reproduction</title><style>"
        "body{font-family:sans-serif;font-size:14px}table{border-collapse:collapse}"
        "td,th{border:1px solid #ccc;padding:4px 6px;text-align:left;vertical-align:top}"
        "</style></head><body>\n"
        "<h1>Claims of Ivanova (2019) and their reproduction</h1>\n"
        f"<p>{_code_ids(escape(summary_line(report['summary'])))} "
        f"turntable {escape(report['version'])}, "
        f"commit <code>{escape(report['git_commit'])}</code>. Sections, equations and "
        "figures in the second column are those of the original paper; a claim the "
        "reproduction adds is marked <i>(addition)</i>, its location says what in the paper "
        "it builds on.</p>\n"
        f"<table>\n<thead><tr>{head}</tr></thead>\n<tbody>\n"
        + "\n".join(rows)
        + "\n</tbody>\n</table>\n"
        + ("<h2>Evidence</h2>\n<ul>\n" + "\n".join(evidence) + "\n</ul>\n" if evidence else "")
        + "</body></html>\n"
    )


def write_reports(
    json_path: str | Path,
    md_path: str | Path,
    params: Mapping[str, Any] | None = None,
    *,
    commit: str = "unknown",
    provenance: Mapping[str, Any] | None = None,
) -> dict[str, Any]:
    """Build the report and write it as JSON and as Markdown; return it."""
    report = build_report(params, commit=commit, provenance=provenance)
    for path, text in ((json_path, to_json(report)), (md_path, to_markdown(report))):
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        write_text(path, text)
    return report
