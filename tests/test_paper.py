"""The article paper/paper.typ: no typed numbers in its prose, and figures that say where they
come from.

Every number of the article must be read from results/claims.json.  The source is parsed
here, without compiling it: math, code (including strings and figure paths), raw text,
comments, references and labels are removed, content blocks inside code (captions, table
cells) are kept, and what remains must not contain a digit.  The article is also
compiled twice, from the figures and the claims report of the pipeline test's build, to
check that the PDF is reproducible and carries the report.
"""

from __future__ import annotations

import html
import json
import re
import shutil
from pathlib import Path

import pytest
import yaml

from ci_build import full_config

# The clean build of the workflow, shared with tests/test_pipeline.py.
from test_pipeline import clean_build, shared_tmp  # noqa: F401
from turntable.provenance import provenance

ROOT = Path(__file__).resolve().parents[1]
# A commit for the build record of the test article (not a real one: it must not be taken
# from the claims report, whose commit is that of the checkout).
BUILT_FROM = "0123456789abcdef0123456789abcdef01234567"
PAPER = ROOT / "paper" / "paper.typ"
#: Figures the workflow draws that the article does not show yet. The tests below require
#: them to be absent from the article, so that adding one makes them fail until it is taken
#: out of this set. (Figures 8 and 9 are in the section "What a film can tell", film.typ.)
NOT_YET_IN_ARTICLE: set[str] = set()
VALUES = ROOT / "paper" / "values.typ"
#: The section "What a film can tell", included from paper.typ; its numbers are read from the
#: results of the film rules (results/film/*.json).
FILM = ROOT / "paper" / "film.typ"
_INCLUDE = re.compile(r'^#include "([^"]+)"\n', re.M)


def article_text() -> str:
    """paper.typ with each `#include "<file>"` line replaced by that file: the article as
    Typst typesets it, in order."""
    text = PAPER.read_text(encoding="utf-8")
    return _INCLUDE.sub(lambda m: (PAPER.parent / m.group(1)).read_text(encoding="utf-8"), text)


_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_-]*")
_KEYWORDS = {"let", "set", "show", "import", "include"}


class _Parser:
    """Split Typst source into prose (returned) and everything else (dropped)."""

    def __init__(self, text: str) -> None:
        self.s = text
        self.i = 0

    def _skip_string(self) -> None:
        self.i += 1
        while self.i < len(self.s) and self.s[self.i] != '"':
            self.i += 2 if self.s[self.i] == "\\" else 1
        self.i += 1

    def _skip_raw(self) -> None:
        fence = "```" if self.s.startswith("```", self.i) else "`"
        end = self.s.find(fence, self.i + len(fence))
        self.i = len(self.s) if end < 0 else end + len(fence)

    def _skip_comment(self) -> bool:
        if self.s.startswith("//", self.i) and (self.i == 0 or self.s[self.i - 1] != ":"):
            end = self.s.find("\n", self.i)
            self.i = len(self.s) if end < 0 else end
            return True
        if self.s.startswith("/*", self.i):
            end = self.s.find("*/", self.i)
            self.i = len(self.s) if end < 0 else end + 2
            return True
        return False

    def markup(self, stop: str | None = None) -> str:
        """Prose of markup up to the closing ``stop`` bracket (or the end)."""
        out: list[str] = []
        depth = 0
        while self.i < len(self.s):
            c = self.s[self.i]
            if self._skip_comment():
                continue
            if c == "\\":
                self.i += 2
            elif c == "`":
                self._skip_raw()
            elif c == "$":
                end = self.i + 1
                while end < len(self.s) and self.s[end] != "$":
                    end += 2 if self.s[end] == "\\" else 1
                self.i = end + 1
            elif c == "@" and _IDENT.match(self.s, self.i + 1):
                self.i = _IDENT.match(self.s, self.i + 1).end()
            elif c == "<" and re.match(r"<[A-Za-z0-9_:.-]+>", self.s[self.i :]):
                self.i = self.s.index(">", self.i) + 1
            elif c == "#":
                self.i += 1
                out.append(" " + self.code_expression() + " ")
            elif stop and c == "[":
                depth += 1
                out.append(c)
                self.i += 1
            elif stop and c == stop:
                if depth == 0:
                    self.i += 1
                    return "".join(out)
                depth -= 1
                out.append(c)
                self.i += 1
            else:
                out.append(c)
                self.i += 1
        return "".join(out)

    def code(self, stop: str) -> str:
        """Skip code up to the closing ``stop`` bracket; return the prose of its content blocks."""
        out: list[str] = []
        while self.i < len(self.s):
            c = self.s[self.i]
            if self._skip_comment():
                continue
            if c == '"':
                self._skip_string()
            elif c == "`":
                self._skip_raw()
            elif c == "[":
                self.i += 1
                out.append(" " + self.markup("]") + " ")
            elif c in "({":
                self.i += 1
                out.append(self.code(")" if c == "(" else "}"))
            elif c == "$":
                self.i += 1
                end = self.s.find("$", self.i)
                self.i = len(self.s) if end < 0 else end + 1
            elif c == stop:
                self.i += 1
                return "".join(out)
            else:
                self.i += 1
        return "".join(out)

    def code_expression(self) -> str:
        """After a ``#``: a keyword statement, a block, or an identifier with calls."""
        m = _IDENT.match(self.s, self.i)
        if self.i < len(self.s) and self.s[self.i] in "({[":
            m = None
        elif m is None:
            return ""
        if m and m.group() in _KEYWORDS:
            # statement: up to the end of the line, brackets balanced
            out: list[str] = []
            self.i = m.end()
            while self.i < len(self.s) and self.s[self.i] != "\n":
                c = self.s[self.i]
                if c in "([{":
                    self.i += 1
                    out.append(self.code({"(": ")", "[": "]", "{": "}"}[c]))
                elif c == '"':
                    self._skip_string()
                else:
                    self.i += 1
            return "".join(out)
        if m:
            self.i = m.end()
        out = []
        while self.i < len(self.s):
            c = self.s[self.i]
            if c == "(":
                self.i += 1
                out.append(self.code(")"))
            elif c == "{":
                self.i += 1
                out.append(self.code("}"))
            elif c == "[":
                self.i += 1
                out.append(self.markup("]"))
            elif c == "." and _IDENT.match(self.s, self.i + 1):
                self.i = _IDENT.match(self.s, self.i + 1).end()
            else:
                break
        return "".join(out)


def prose(text: str) -> str:
    """The prose of a Typst source: what a reader sees that is typed in the source."""
    return _Parser(text).markup()


def digits_in_prose(text: str) -> list[str]:
    """Each digit of the prose, with some context."""
    p = prose(text)
    return [p[max(0, m.start() - 30) : m.end() + 30] for m in re.finditer(r"\d", p)]


# The parser itself -----------------------------------------------------------------------


@pytest.mark.parametrize(
    "source",
    [
        "The ratio is 535 here.",
        '#figure(image("a.png"), caption: [made at 3 pm])',
        "#align(center)[version 2 of it]",
        "A table #table([a], [b 7])",
        "#{ let x = 1; [cell 9] }",
    ],
)
def test_parser_finds_typed_numbers(source: str) -> None:
    assert digits_in_prose(source)


@pytest.mark.parametrize(
    "source",
    [
        "Math $x = 2.5 + 10^(-3)$ is fine.",
        "A reference @eq-2 and a label <fig-6> and a citation @ivanova2019.",
        '#image("../figures/fig2_spectrum.pdf", width: 66%)',
        'Raw `scripts/fig3_modal_terms.py` and #num(rep("a", "b"), digits: 3).',
        "// a comment with 42\nText without numbers.",
        '#let k0 = param("k_paper")\n#set text(size: 10.5pt)\nProse.',
        "Escaped \\$ dollar and text.",
    ],
)
def test_parser_ignores_math_code_refs_and_paths(source: str) -> None:
    assert digits_in_prose(source) == []


# The article -----------------------------------------------------------------------------


@pytest.mark.parametrize("source", [PAPER, FILM], ids=lambda p: p.name)
def test_no_typed_numbers_in_the_prose(source: Path) -> None:
    found = digits_in_prose(source.read_text(encoding="utf-8"))
    assert found == [], f"numbers typed into the prose (read them from the results): {found}"


def _figures(text: str) -> list[tuple[str, str]]:
    """(image path, caption source) of every figure(...) call."""
    out = []
    for m in re.finditer(r"#figure\(", text):
        p = _Parser(text)
        p.i = m.end()
        start = p.i
        p.code(")")
        body = text[start : p.i]
        image = re.search(r'image\("([^"]+)"', body)
        caption = re.search(r"caption:\s*\[(.*)\]", body, re.S)
        out.append((image.group(1) if image else "", caption.group(1) if caption else ""))
    return out


def test_every_figure_comes_from_figures_and_names_its_script() -> None:
    figures = [f for f in _figures(article_text()) if f[0]]  # tables are figures too
    assert figures
    stems = []
    for path, caption in figures:
        assert path.startswith("../figures/"), path
        stem = Path(path).stem
        stems.append(stem)
        assert f'#script-link("{stem}")' in caption, (path, caption)
        assert (ROOT / "scripts" / f"{stem}.py").is_file(), stem
    made = sorted(p.stem for p in (ROOT / "scripts").glob("fig*.py"))
    assert sorted(stems) == sorted(set(made) - NOT_YET_IN_ARTICLE)
    assert set(made) >= NOT_YET_IN_ARTICLE


def test_numbers_come_from_the_claims_report() -> None:
    text = PAPER.read_text(encoding="utf-8")
    values = VALUES.read_text(encoding="utf-8")
    assert 'json("../results/claims.json")' in values
    assert re.search(r'pdf\.attach\(\s*"\.\./results/claims\.json"', text)
    assert '#import "values.typ"' in text
    # every claim id used in the text exists in the registry
    from turntable import claims

    used = set(re.findall(r'(?:rep|claim|verdict|cid)\("([a-z0-9_.]+)"', text))
    assert used
    assert used <= set(claims.claim_ids())


# Compilation ------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def paper_tree(clean_build: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:  # noqa: F811
    """A project tree holding what the article reads: the figures and the claims report of
    the pipeline test's clean build (whose claims section is the project's), the article's
    sources."""
    tree = tmp_path_factory.mktemp("paper-tree")
    shutil.copytree(clean_build / "figures", tree / "figures")
    shutil.copytree(ROOT / "paper", tree / "paper", ignore=shutil.ignore_patterns("*.pdf"))
    config = full_config()
    assert (
        full_config(yaml.safe_load((clean_build / "config/config.yaml").read_text()))["claims"]
        == (config["claims"])
    )
    (tree / "results").mkdir()
    shutil.copy2(clean_build / "results/claims.json", tree / "results/claims.json")
    # what the section "What a film can tell" reads (FILM_RESULTS of workflow/rules/film.smk)
    (tree / "results" / "film").mkdir()
    for path in (clean_build / "results" / "film").glob("*.json"):
        shutil.copy2(path, tree / "results" / "film" / path.name)
    # As scripts/build_paper.py writes it; a made-up commit, distinct from the claims report's.
    record = provenance(ROOT) | {"git_commit": BUILT_FROM, "git_dirty": True}
    build = {"provenance": record, "repository": config["paper"]["repository"]}
    (tree / "results" / "build.json").write_text(json.dumps(build))
    return tree


def test_pdf_names_the_commit_that_built_it_and_links_the_scripts(paper_tree: Path) -> None:
    import typst

    main = str(paper_tree / "paper" / "paper.typ")
    built = json.loads(
        typst.query(main, "<built-from>", field="value", one=True, root=str(paper_tree))
    )
    assert built == {"commit": BUILT_FROM, "dirty": True}
    links = set(json.loads(typst.query(main, "link", field="dest", root=str(paper_tree))))
    repository = full_config()["paper"]["repository"]
    for stem in sorted(p.stem for p in (ROOT / "scripts").glob("fig*.py")):
        linked = f"{repository}/blob/{BUILT_FROM}/scripts/{stem}.py" in links
        assert linked != (stem in NOT_YET_IN_ARTICLE), stem


def test_pdf_is_reproducible_and_carries_the_report(paper_tree: Path) -> None:
    import typst

    def build() -> bytes:
        return typst.compile(
            str(paper_tree / "paper" / "paper.typ"),
            root=str(paper_tree),
            format="pdf",
            ignore_system_fonts=True,
            timestamp=0,
        )

    first, second = build(), build()
    assert first == second
    assert first.startswith(b"%PDF")
    assert b"claims.json" in first


def test_article_numbers_its_figures_as_their_files() -> None:
    """Figure N of the article is figures/figN_*: the figures appear in that order, in place."""
    figures = [f for f in _figures(article_text()) if f[0]]  # tables are figures too
    numbers = [int(re.match(r"fig(\d+)_", Path(path).stem).group(1)) for path, _ in figures]
    assert numbers == list(range(1, len(figures) + 1))
    assert "placement:" not in article_text()  # no floats reordering them


#: Plain-text mathematics of the registry that the appendix must not show untypeset.
ASCII_MATH = re.compile(
    r"\b(mu0|alpha[12]?|beta|delta|sigma|lambda|eps|Omega|omega|gamma|infinity|sqrt|P4)\b"
    r"|\b[ew][12]\b|\b[xyzru]0\b|\b[vw][xyz]\b|\b[xyr]_[a-z]|_\{|\^|<=|>=|->|~|exp\(2 pi\)"
    # the angular velocity left as a Latin w (w, w_h)
    r"|\bw\b|_[+-]"
)


def test_appendix_typesets_the_registry_mathematics(paper_tree: Path) -> None:
    """The registry's strings, as the appendix shows them (show: ascii-math, one run of text per
    sentence), exported to HTML:
    no plain-text mathematics is left, nothing is swallowed (balanced parentheses, final
    full stops), and claim ids are left as they are."""
    import typst

    doc = paper_tree / "paper" / "ascii_math_check.typ"
    doc.write_text(
        '#import "values.typ": *\n#show: ascii-math\n'
        "#for id in report.order {\n  let c = claim(id)\n"
        "  for s in (c.paper_value.text, c.summary, c.evidence, id) { par(sentences(s)) }\n}\n",
        encoding="utf-8",
    )
    page = typst.compile(str(doc), root=str(paper_tree), format="html").decode()
    # Subscripts and superscripts marked (x<sub>0</sub> -> x⌄0), then the tags dropped.
    marked = page.replace("<sub>", "⌄").replace("<sup>", "⌃")
    paragraphs = [re.sub(r"<[^>]+>", "", p) for p in re.findall(r"<p>(.*?)</p>", marked, re.S)]
    report = json.loads((paper_tree / "results" / "claims.json").read_text(encoding="utf-8"))
    strings = [
        s
        for cid in report["order"]
        for s in (
            report["claims"][cid]["paper_value"]["text"],
            report["claims"][cid]["summary"],
            report["claims"][cid]["evidence"],
            cid,
        )
    ]
    assert len(paragraphs) == len(strings)
    for shown, source in zip(paragraphs, strings, strict=True):
        shown = html.unescape(shown)
        if source in report["order"]:
            assert shown == source  # a claim id is not typeset
            continue
        left = [m.group(0) for m in ASCII_MATH.finditer(shown)]
        assert left == [], (left, shown)
        # Parentheses are kept, except those of a raised exponent: ^(3/2), exp(2 pi).
        kept = re.sub(r"\^\([^()]*\)|exp\(2 pi\)", "", source)
        assert shown.count("(") == kept.count("("), (shown, source)
        assert shown.count(")") == kept.count(")"), (shown, source)
        assert shown.endswith(".") == source.endswith("."), (shown, source)
    assert "<sub>" in page
    assert "<sup>" in page
    # "~=" is approximately: N > e^(2 pi) ≈ 535, not ∼ (of the order of)
    assert any("e⌃2π ≈ 535" in html.unescape(p) for p in paragraphs)


def test_verdict_lists_keep_the_paper_apart_from_the_additions() -> None:
    """The lists by verdict count the paper's statements and the additions separately."""
    text = PAPER.read_text(encoding="utf-8")
    section = text.split("= The verdicts <sec-verdicts>", 1)[1].split("\n= ", 1)[0]
    assert section.index('verdict-lists("paper")') < section.index('verdict-lists("project")')
    assert "verdict-lists()" not in text


# The section "What a film can tell" ---------------------------------------------------------


def test_film_section_is_included_before_the_verdicts() -> None:
    """paper.typ includes film.typ with one line, directly before the verdicts."""
    text = PAPER.read_text(encoding="utf-8")
    assert text.count('#include "film.typ"') == 1
    assert '#include "film.typ"\n= The verdicts <sec-verdicts>' in text
    film = FILM.read_text(encoding="utf-8")
    assert film.lstrip("/ \n").split("\n")[0]  # a comment says what it is
    for path in ("../results/film/measurability.json", "../results/film/synthetic.json"):
        assert f'json("{path}")' in film
    assert 'json("../results/film/" + name + ".json")' in film
    assert "= What a film can tell" in film


def _film_section(tree: Path) -> str:
    """The film section compiled alone (with the article's helpers) to HTML, as text."""
    import typst

    doc = tree / "paper" / "film_only.typ"
    # the heading the section refers to, then the section
    doc.write_text(
        '#set heading(numbering: "1.")\n= Slipping or rolling resistance? <sec-comparison>\n'
        '#include "film.typ"\n',
        encoding="utf-8",
    )
    page = typst.compile(str(doc), root=str(tree), format="html").decode()
    text = " ".join(html.unescape(re.sub(r"<[^>]+>", " ", page)).split())
    return text.replace("( ", "(").replace(" )", ")")


def test_film_section_prints_the_numbers_of_the_results(paper_tree: Path, tmp_path: Path) -> None:
    """The section prints what the JSON files hold: with made-up values put into them, the
    compiled text shows those values; the films are marked synthetic, and a fit not marked
    synthetic stops the build."""
    tree = Path(shutil.copytree(paper_tree, tmp_path / "tree"))
    folder = tree / "results" / "film"
    truth = json.loads((folder / "synthetic.json").read_text())
    name, spec = next(iter(truth["films"].items()))
    key = {"slipping": "mu0", "rolling_resistance": "delta"}[spec["model"]]
    real = json.loads((folder / f"{name}.json").read_text())
    text = _film_section(tree)
    assert "SYNTHETIC" in text
    assert "What a film can tell" in text
    # the numbers of the build are there, as the section formats them
    rms = real[spec["model"]]["rms_residual_m"] * 1000
    assert f"{rms:.2g} mm" in text, text
    made_up = json.loads((folder / f"{name}.json").read_text())
    entry = made_up[spec["model"]]
    entry.update({key: 2.5, f"{key}_stderr": 0.25, f"{key}_ci95": [1.53, 4.08]})
    entry["rms_residual_m"] = 0.000777
    made_up["selection"]["aicc_difference"] = 43.0
    (folder / f"{name}.json").write_text(json.dumps(made_up))
    measure = json.loads((folder / "measurability.json").read_text())
    measure["indistinguishable_above_mu0"] = 37.0
    measure["reliable_relative_error"] = 0.17
    measure["reliable_mu0_range"] = [1e-3, 6100.0]
    (folder / "measurability.json").write_text(json.dumps(measure))
    spec_text = _film_section(tree)
    for shown in ("2.50 ± 0.25", "1.53 to 4.08", "0.78 mm", "(43)", "> 37", "0.17", "6100"):
        assert shown in spec_text, (shown, spec_text)
    made_up["data"]["synthetic"] = False
    (folder / f"{name}.json").write_text(json.dumps(made_up))
    import typst

    with pytest.raises(typst.TypstError, match="not marked synthetic"):
        _film_section(tree)
