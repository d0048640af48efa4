"""Pages of the HTML report: the claims table with verdicts, every figure with its caption."""

from __future__ import annotations

import base64
import re
import shutil
from pathlib import Path

import pytest
import yaml

from test_pipeline import NAMES, clean_build, run_snakemake, shared_tmp  # noqa: F401
from turntable.claims import VERDICTS
from turntable.claims.report import to_html

ROOT = Path(__file__).resolve().parents[1]


def _fake_report() -> dict:
    verdicts = {"a.one": "confirmed", "b.two": "refined", "c.three": "failed"}
    claims = {
        cid: {
            "verdict": v,
            "where": {"label": "Sec. 2, Fig. 4"},
            "claim": f"claim <{cid}> & more",
            "paper_value": {"text": "x0 = 0"} if cid != "c.three" else None,
            "summary": f"reproduced {cid}",
        }
        for cid, v in verdicts.items()
    }
    summary = {v: sum(x == v for x in verdicts.values()) for v in VERDICTS}
    return {
        "order": list(verdicts),
        "claims": claims,
        "summary": summary | {"total": 3},
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
    assert "3 claims: 1 confirmed, 1 refined, 1 failed" in page
    assert "original paper" in page


def test_claims_page_is_in_the_report() -> None:
    rules = (ROOT / "workflow" / "rules" / "report.smk").read_text()
    assert re.search(r'report\(\s*"results/claims.html"', rules)
    assert '"results/claims.html"' in (ROOT / "Snakefile").read_text()


@pytest.fixture(scope="module")
def gallery(clean_build: Path, tmp_path_factory: pytest.TempPathFactory) -> str:  # noqa: F811
    workdir = tmp_path_factory.mktemp("gallery") / "w"
    shutil.copytree(clean_build, workdir, symlinks=True)
    proc = run_snakemake(workdir, "results/figures.html")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return (workdir / "results" / "figures.html").read_text(encoding="utf-8"), workdir


def test_every_figure_with_its_caption(gallery) -> None:
    page, workdir = gallery
    figures = re.findall(r'<figure id="([^"]+)">(.*?)</figure>', page, re.S)
    assert [name for name, _ in figures] == NAMES
    config = yaml.safe_load((workdir / "config" / "config.yaml").read_text())
    for name, body in figures:
        png = (workdir / "figures" / f"{name}.png").read_bytes()
        assert base64.b64encode(png).decode() in body, name
        caption = body.split("<figcaption>", 1)[1]
        assert "{{" not in caption
        assert len(re.sub(r"<[^>]+>", "", caption)) > 100, name
    # the captions' templates are filled from the configuration
    fig4 = dict(figures)["fig4_trajectories"]
    text = re.sub(r"<[^>]+>", "", fig4.split("<figcaption>", 1)[1])
    for m in config["fig4_trajectories"]["mu0"]:
        assert str(m) in text, m
