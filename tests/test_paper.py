"""The article paper/paper.typ: no typed numbers in its prose, and figures that say where they
come from.

Every number of the article must be read from results/claims.json.  The source is parsed
here, without compiling it: math, code (including strings and figure paths), raw text,
comments, references and labels are removed, content blocks inside code (captions, table
cells) are kept, and what remains must not contain a digit.  The article compiled from
the figures and the claims report of a build is tested in tests/test_build_outputs.py.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
# A commit for the build record of the test article (not a real one: it must not be taken
# from the claims report, whose commit is that of the checkout).
BUILT_FROM = "0123456789abcdef0123456789abcdef01234567"
PAPER = ROOT / "paper" / "paper.typ"
#: Figures the workflow draws that the article does not show: those of fitting a film, shown
#: by the report's page "What a film can tell" and docs/fitting.md. The tests below require
#: them to be absent from the article, so that adding one makes them fail until it is taken
#: out of this set.
NOT_YET_IN_ARTICLE: set[str] = {"fig8_measurability", "fig9_fit", "fig10_video"}
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


def test_no_typed_numbers_in_the_prose() -> None:
    found = digits_in_prose(article_text())
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


def test_every_claim_the_article_quotes_is_registered() -> None:
    """Every claim id the article reads a value or verdict of exists in the registry."""
    text = PAPER.read_text(encoding="utf-8")
    from turntable import claims

    used = set(re.findall(r'(?:rep|claim|verdict|cid|vb|val|lim)\("([a-z0-9_.]+)"', text))
    assert used
    assert used <= set(claims.claim_ids())


def test_article_numbers_its_figures_as_their_files() -> None:
    """Figure N of the article is figures/figN_*: the figures appear in that order, in place."""
    figures = [f for f in _figures(article_text()) if f[0]]  # tables are figures too
    numbers = [int(re.match(r"fig(\d+)_", Path(path).stem).group(1)) for path, _ in figures]
    assert numbers == list(range(1, len(figures) + 1))
    assert "placement:" not in article_text()  # no floats reordering them
