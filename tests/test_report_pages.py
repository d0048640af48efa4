"""Pages of the HTML report: the claims table with verdicts, every figure with its caption."""

from __future__ import annotations

import io
import re
from pathlib import Path
from types import SimpleNamespace

import pytest

from ci_build import full_config
from turntable.claims.report import html_math, summarize, to_html

ROOT = Path(__file__).resolve().parents[1]


def _fake_report() -> dict:
    verdicts = {"a.one": "confirmed", "b.two": "refined", "c.three": "failed"}
    claims = {
        cid: {
            "id": cid,
            "source": "project" if cid == "b.two" else "paper",
            "verdict": v,
            "where": {"label": "Sec. 2, Fig. 4"},
            "claim": f"claim <{cid}> & more",
            "paper_value": {"text": "x0 = 0"} if cid != "c.three" else None,
            "summary": f"reproduced {cid}",
        }
        for cid, v in verdicts.items()
    }
    return {
        "order": list(verdicts),
        "claims": claims,
        "summary": summarize(list(claims.values())),
        "version": "0.1.0",
        "git_commit": "abc",
    }


def test_claims_page_has_one_row_per_claim_with_its_verdict() -> None:
    page = to_html(_fake_report())
    rows = re.findall(r"<tr><td>(.*?)</td></tr>", page)
    assert len(rows) == 3
    for row, (cid, verdict) in zip(
        rows, [("a.one", "confirmed"), ("b.two", "refined"), ("c.three", "failed")], strict=True
    ):
        assert f"<code>{cid}</code>" in row
        assert re.search(rf'<b style="color:#[0-9a-f]{{6}}">{verdict}</b>', row)
    assert "claim &lt;a.one&gt; &amp; more" in page  # escaped
    assert (
        "3 claims. Of the 2 of the paper: 1 confirmed, 0 refined, 0 corrected, 0 undecidable, "
        "1 failed; of the 1 added by the reproduction: 1 refined. Failed: <code>c.three</code>."
    ) in page
    assert "<code>b.two</code> <i>(addition)</i>" in page
    assert "original paper" in page


@pytest.mark.parametrize(
    ("text", "html"),
    [
        pytest.param("mu0^-2", "μ<sub>0</sub><sup>−2</sup>", id="index-and-power"),
        pytest.param("N > exp(2 pi) ~= 535", "N &gt; e<sup>2π</sup> ≈ 535", id="exp-2pi"),
        pytest.param("error ~ mu0^-1", "error ∼ μ<sub>0</sub><sup>−1</sup>", id="order-of"),
        pytest.param(
            "gamma x w, w = r + i v, w1, w_h, v or w.",
            "γ × ω, ω = r + i v, ω<sub>1</sub>, ω<sub>h</sub>, v or ω.",
            id="angular-velocity",
        ),
        pytest.param("w.r.t. a wall", "w.r.t. a wall", id="w-in-words"),
        pytest.param(
            "|1 + i lambda_+|, lambda_- and lambda_{1,2}",
            "|1 + i λ<sub>+</sub>|, λ<sub>−</sub> and λ<sub>1,2</sub>",
            id="plus-minus-subscripts",
        ),
        pytest.param("|alpha2|/beta", "|α<sub>2</sub>|/β", id="greek"),
        pytest.param(
            "error 6.9e-25 <= 1e-06",
            "error 6.9×10<sup>−25</sup> ≤ 10<sup>−6</sup>",
            id="scientific",
        ),
        pytest.param(
            "y0 = (k wy(0) + vx(0))/k",
            "y<sub>0</sub> = (k ω<sub>y</sub>(0) + v<sub>x</sub>(0))/k",
            id="components",
        ),
        pytest.param("ln N - 2 pi", "ln N − 2 π", id="minus"),
        pytest.param("z- < 1% of z+", "z<sub>−</sub> &lt; 1% of z<sub>+</sub>", id="parts"),
        pytest.param(
            "mu0_dim, mu0*, sigma_g, lambda_{1,2}",
            "μ<sub>0</sub><sup>dim</sup>, μ<sub>0</sub><sup>*</sup>, σ<sub>g</sub>, "
            "λ<sub>1,2</sub>",
            id="subscripts",
        ),
        pytest.param(
            "spectrum.alpha1_peak, alphabet, mu",
            "spectrum.alpha1_peak, alphabet, μ",
            id="ids-untouched",
        ),
        pytest.param("a < b & c", "a &lt; b &amp; c", id="escaped"),
        pytest.param(
            "at the frequency beta. Then x0, vx.",
            "at the frequency β. Then x<sub>0</sub>, v<sub>x</sub>.",
            id="before-a-full-stop",
        ),
        pytest.param("turntable.beta, beta.x", "turntable.beta, beta.x", id="dotted-names"),
        pytest.param(
            "x_c e1 + y_c e2, not e12",
            "x<sub>c</sub> e<sub>1</sub> + y<sub>c</sub> e<sub>2</sub>, not e12",
            id="kernel",
        ),
    ],
)
def test_claims_page_typesets_the_plain_text_mathematics(text: str, html: str) -> None:
    assert html_math(text) == html


def test_claims_page_shows_no_plain_text_mathematics() -> None:
    """The claim, paper's value and reproduced columns go through html_math."""
    report = _fake_report()
    report["claims"]["a.one"]["summary"] = "mu0 = 0.1, alpha1 > 0"
    report["claims"]["a.one"]["paper_value"] = {"text": "N > exp(2 pi)"}
    page = to_html(report)
    for ascii_math in ("mu0", "alpha1", "exp(2 pi)"):
        assert ascii_math not in page
    assert "μ<sub>0</sub> = 0.1, α<sub>1</sub> &gt; 0" in page


# Captions of the report ----------------------------------------------------------------

CAPTIONS = sorted((ROOT / "workflow" / "report").glob("*.rst"))

#: Plain-text mathematics that a caption must typeset (with :math:) instead.
ASCII_MATH = re.compile(
    r"\b(mu0|alpha[12]?|beta|delta|Omega|omega|lambda|sigma|eps|pi)\b|\^-?\d|->|\|\w+\|"
)


def _docutils_messages(text: str) -> str:
    """What docutils reports (level info and above) while rendering ``text`` as Snakemake does."""
    from docutils.core import publish_parts

    stream = io.StringIO()
    publish_parts(
        text,
        writer="html",
        settings_overrides={"report_level": 1, "halt_level": 5, "warning_stream": stream},
    )
    return stream.getvalue()


def _rendered(rst: Path) -> str:
    """The caption as Snakemake renders it: a Jinja template of the configuration."""
    import jinja2

    config = full_config()
    template = jinja2.Template(rst.read_text(encoding="utf-8"))
    return template.render(snakemake=SimpleNamespace(config=config))


@pytest.mark.parametrize("rst", CAPTIONS, ids=[p.stem for p in CAPTIONS])
def test_caption_renders_without_docutils_messages(rst: Path) -> None:
    """No error or warning of docutils (e.g. |alpha2| read as an undefined substitution)."""
    assert _docutils_messages(_rendered(rst)) == "", rst.name


@pytest.mark.parametrize("rst", CAPTIONS, ids=[p.stem for p in CAPTIONS])
def test_caption_typesets_its_mathematics(rst: Path) -> None:
    """Outside :math:`...` and ``literals``, no ASCII mathematics such as mu0 or |alpha2|."""
    text = re.sub(r":math:`[^`]*`|``[^`]*``", " ", _rendered(rst))
    assert ASCII_MATH.findall(text) == [], f"{rst.name}: {ASCII_MATH.findall(text)}"


def test_a_broken_caption_is_noticed() -> None:
    """The two tests above do catch an undefined substitution and plain-text mathematics."""
    bad = "decays at the slipping |alpha2| for mu0 -> 0."
    assert "Undefined substitution" in _docutils_messages(bad)
    assert ASCII_MATH.findall(bad)


def test_claims_page_gives_the_evidence_of_each_verdict() -> None:
    """Below the table, as in claims.md: each claim's evidence with the value that decides
    its verdict, so that the page says why a verdict is refined, corrected or undecidable."""
    report = _fake_report()
    for cid, claim in report["claims"].items():
        claim |= {
            "evidence": f"why {cid} is {claim['verdict']}",
            "decisive": "err",
            "reproduced": {"err": 0.5},
            "tolerance": {"err": {"<=": 1.0}},
            "expected": claim["verdict"],
        }
    page = to_html(report)
    evidence = page.split("<h2>Evidence</h2>", 1)[1]
    items = re.findall(r"<li>(.*?)</li>", evidence)
    assert len(items) == 3
    for item, cid in zip(items, report["order"], strict=True):
        verdict = report["claims"][cid]["verdict"]
        assert item.startswith(f"<code>{cid}</code> ({verdict}; decided by <code>err = 0.5 ")
        assert f"why {cid} is {verdict}" in item


SCRIPT = "<script>alert('x')</script>"


def _report_with_script_everywhere() -> dict:
    report = _fake_report()
    for claim in report["claims"].values():
        claim |= {
            "where": {"label": SCRIPT},
            "claim": SCRIPT,
            "summary": SCRIPT,
            "paper_value": {"text": SCRIPT},
            "evidence": SCRIPT,
            "method": SCRIPT,
            "decisive": "err",
            "reproduced": {"err": SCRIPT},
            "tolerance": {"err": {"<=": 1.0}},
            "expected": claim["verdict"],
        }
    report["version"] = report["git_commit"] = SCRIPT
    return report


def test_claims_page_shows_a_label_holding_a_script_as_text() -> None:
    page = to_html(_report_with_script_everywhere())
    assert "<script" not in page
    assert "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt;" in page
    assert page.count("&lt;script&gt;") == 2 + 3 * 6  # version, commit; 6 places a claim


def test_claims_markdown_shows_a_label_holding_a_script_as_text() -> None:
    """In Markdown a "<" before a letter or "/" would open an HTML tag: it is escaped (in a
    code span, such as the commit's, it is text anyway)."""
    from turntable.claims.report import to_markdown

    text = to_markdown(_report_with_script_everywhere())
    rows = [line for line in text.splitlines() if line.startswith("| `")]
    assert len(rows) == 3
    assert all(r"\<script>alert('x')\</script>" in row for row in rows)
    outside_code = re.sub(r"`[^`]*`", "", text)
    assert re.search(r"(?<!\\)<[A-Za-z/]", outside_code) is None


def _film_inputs(text: str) -> tuple[dict, dict, dict, dict]:
    """What `film_page` reads, for one SYNTHETIC film whose name, note and warnings are
    ``text``."""
    measure = {
        "setup": {
            "radius_m": 0.01,
            "omega_rad_s": 3.5,
            "k": 0.4,
            "fps": 240.0,
            "noise_m": 2e-4,
            "duration_s": 10.0,
        },
        "table": {"mu0": [0.1, 1.0], "mu0_stderr": [0.01, 0.5], "selection_probability": [1, 0.5]},
        "reliable_mu0_range": [0.1, 1.0],
        "indistinguishable_above_mu0": 0.8,
        "reliable_relative_error": 0.2,
        "selection_probability": 0.95,
    }
    truth = {"note": text, "films": {text: {"model": "slipping", "coefficient": 3.0}}}
    entry = {
        "mu0": 3.0,
        "mu0_stderr": 0.003,
        "mu0_ci95": [2.99, 3.01],
        "rms_residual_m": 2e-4,
        "residual_lag1_autocorrelation": -0.004,
        "residual_lag1_white_sd": 0.014,
    }
    fit = {
        "data": {"synthetic": True, "n_frames": 2401, "duration_s": 10.0, "turntable_turns": 5.6},
        "slipping": entry,
        "selected": "slipping",
        "selection": {"aicc_difference": 5486.1, "akaike_weights": {"slipping": 1.0}},
        "warnings": [text, text],
    }
    return measure, truth, {text: fit}, {"fig8_measurability": "<figure>8</figure>"}


def test_film_page_shows_a_film_holding_a_script_as_text() -> None:
    from turntable.fit._page import film_page

    page = film_page(*_film_inputs(SCRIPT))
    assert "<script" not in page
    escaped = "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt;"
    assert page.count(escaped) == 4  # the note, the film's name, its two warnings
    assert f"{escaped}; {escaped}</td>" in page
    assert "<figure>8</figure><h2>Synthetic films" in page  # a figure's HTML as it is
    assert "for every &mu;<sub>0</sub> of the grid up to 1; beyond" in page
    assert "<td>&mu;<sub>0</sub> = 3.0000 ± 0.0030</td><td>2.9900 to 3.0100</td>" in page


def test_a_figure_whose_name_and_image_hold_a_script_shows_them_as_text(tmp_path: Path) -> None:
    """workflow/scripts/report_figure.py: the id, the alt text, the name and the image's
    path are escaped; the caption is docutils' HTML."""
    import importlib.util

    spec = importlib.util.spec_from_file_location(
        "report_figure", ROOT / "workflow" / "scripts" / "report_figure.py"
    )
    assert spec is not None
    assert spec.loader is not None
    report_figure = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(report_figure)
    image = tmp_path / "<script>.png"
    image.write_bytes(b"PNG")
    rst = tmp_path / "caption.rst"
    rst.write_text("A *caption*.", encoding="utf-8")
    name = 'fig"><script>alert(1)</script>'
    html = report_figure.figure_html(name, str(image), str(rst), "image/png", {})
    assert "<script" not in html
    assert html.startswith('<figure id="fig&#34;&gt;&lt;script&gt;alert(1)&lt;/script&gt;">')
    assert 'alt="fig&#34;&gt;&lt;script&gt;' in html
    assert f"<code>{tmp_path}/&lt;script&gt;.png</code>" in html
    assert "<em>caption</em>" in html


def test_site_claims_table_shows_a_label_holding_a_script_as_text(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """docs/site_pages.py: the claims table of the site escapes every text of a claim."""
    import importlib.util
    import json

    spec = importlib.util.spec_from_file_location("site_pages", ROOT / "docs" / "site_pages.py")
    assert spec is not None
    assert spec.loader is not None
    site_pages = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(site_pages)
    (tmp_path / "results").mkdir()
    report = _report_with_script_everywhere()
    (tmp_path / "results" / "claims.json").write_text(json.dumps(report), encoding="utf-8")
    monkeypatch.setattr(site_pages, "ROOT", tmp_path)
    monkeypatch.setattr(site_pages, "OUT", tmp_path / "generated")
    site_pages.claims_table()
    text = (tmp_path / "generated" / "claims.rst").read_text(encoding="utf-8")
    table = text.split(".. raw:: html\n\n", 1)[1]
    assert "<script" not in table
    assert table.count("&lt;script&gt;") == 3 * 3  # label, claim and summary of 3 claims
    assert all(line.startswith("   <") for line in table.splitlines())
    assert table.count("<tr><td><code>") == 3
