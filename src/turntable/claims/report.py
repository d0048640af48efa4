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


def printed_values(claim: Mapping[str, Any]) -> str:
    """Return ``key = value: what it measures (its parameters)`` for every number of the claim
    the article prints, from its record (`turntable.claims.Quantity`)."""
    from turntable.claims._core import Quantity

    lines = []
    for key, record in claim.get("quantities", {}).items():
        label = Quantity(**record).label()
        lines.append(
            f"`{key}` = {claim['reproduced'][key]}: {record['of']}"
            + (f" ({label})" if label else "")
        )
    return "; ".join(lines)


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


#: The title of the claims table, in Markdown and in HTML.
TITLE = "Claims of Ivanova (2019) and their reproduction"
#: The columns of the Markdown table and of the HTML page.
HEADINGS = ("id", "where in the paper", "claim", "paper's value", "reproduced", "verdict")
#: Something that would open an HTML tag in Markdown: a "<" before a letter, "/", "!" or "?".
_MARKDOWN_TAG = re.compile(r"<(?=[A-Za-z/!?])")


def _cell(text: Any) -> str:
    """Text as one cell of a Markdown table: "|" and a tag's "<" escaped, lines joined."""
    return _MARKDOWN_TAG.sub(r"\\<", str(text).replace("|", "\\|").replace("\n", " "))


def to_markdown(report: Mapping[str, Any]) -> str:
    """Render a report as a Markdown document with one table row per claim.

    Parameters
    ----------
    report : mapping
        A claims report (`build_report`, or ``results/claims.json`` read back).

    Returns
    -------
    str
        The counts, the meaning of each verdict, the table, then the evidence, the
        reproduced values with their bounds, the numbers the article prints with what each
        is and where it is computed, and the method of each claim (template
        ``turntable/templates/claims.md.j2``). A cell's text stays text: a ``|`` and a
        ``<`` that would open an HTML tag are escaped.

    See Also
    --------
    to_html : The same table as an HTML page.
    """
    from turntable._templates import render

    return render(
        "claims.md.j2",
        title=TITLE,
        headings=HEADINGS,
        report=report,
        summary=summary_line(report["summary"]),
        meanings={v: VERDICT_MEANINGS[v] for v in VERDICTS},
        cell=_cell,
        paper_value=_paper_value,
        decisive_value=decisive_value,
        values_and_bounds=values_and_bounds,
        printed_values=printed_values,
    )


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
#: alpha1, sigma_g, lambda_{1,2} and lambda_+, vx and wy, x_c and e1, the angular velocity w
#: (with an index or a subscript: w1, w_h), the cross product "gamma x", z+ and z-, sqrt, the
#: symbols, and a minus between spaces.
_MATH_TOKEN = re.compile(
    r"exp\(2 pi\)"
    r"|\bgamma x\b"
    r"|\b\d(?:\.\d+)?e[-+]?\d+\b"
    r"|\^(?:\([^()]*\)|[-+]?\d+(?:\.\d+)?)"
    r"|(?<![\w.])(?:" + "|".join(sorted(_GREEK, key=len, reverse=True)) + r")\d*"
    r"(?:_(?:c|g|h|dim)\b|_\{[^}]*\}|_[+-])?\*?(?!\w|\.\w)"
    r"|(?<![\w.])[xyzru]0\*?(?!\w|\.\w)"
    r"|(?<![\w.])[xy]_c(?!\w|\.\w)|(?<![\w.])e[12](?!\w|\.\w)"
    r"|(?<![\w.])[vw][xyz](?!\w|\.\w)"
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

    Parameters
    ----------
    report : mapping
        A claims report (`build_report`, or ``results/claims.json`` read back).

    Returns
    -------
    str
        The page (template ``turntable/templates/claims.html.j2``, escaped by Jinja2: any
        text of the report is shown as text). The columns are those of `to_markdown`; the
        verdict is coloured. Shown in the HTML report of the workflow (rule
        ``claims_table``).

    See Also
    --------
    html_math : The plain-text mathematics of a claim, typeset.
    """
    from turntable._templates import escape, markup, render

    summary = re.sub(r"`([^`]+)`", r"<code>\1</code>", str(escape(summary_line(report["summary"]))))
    return render(
        "claims.html.j2",
        title=TITLE,
        headings=HEADINGS,
        report=report,
        summary=markup(summary),
        colours=_VERDICT_COLOURS,
        evidence=[
            (cid, c) for cid in report["order"] if "evidence" in (c := report["claims"][cid])
        ],
        math=lambda text: markup(html_math(str(text))),
        paper_value=_paper_value,
        decisive_value=decisive_value,
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
