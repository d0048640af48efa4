"""What a build of the workflow writes, read by the tests of the package's own files.

Every test here reads the shared build of tests/ci_build.py (``clean_build``, made once
per test run, see tests/conftest.py) or its plan (``build_record``):
they are tests of the workflow's outputs and cost a Snakemake build, unlike the rest of
test_paper.py, test_fit_cli.py, test_report_pages.py and test_study.py, from which they
come.
"""

from __future__ import annotations

import base64
import html
import json
import re
import shutil
from pathlib import Path

import pytest
import yaml

from ci_build import CONFIG, full_config, job_counts
from test_paper import BUILT_FROM, NOT_YET_IN_ARTICLE
from test_pipeline import NAMES
from turntable import film
from turntable.fit import plot as fitplot
from turntable.provenance import provenance

ROOT = Path(__file__).resolve().parents[1]


# The article compiled from the build (paper/paper.typ) --------------------------------------


@pytest.fixture(scope="module")
def paper_tree(clean_build: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A project tree holding what the article reads: the figures and the claims report of
    the shared build (whose claims section is the project's), the article's
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
    # As scripts/build_paper.py writes it; a made-up commit, distinct from the claims report's.
    record = provenance(ROOT) | {"git_commit": BUILT_FROM, "git_dirty": True}
    build = {"provenance": record, "repository": REPOSITORY}
    (tree / "results" / "build.json").write_text(json.dumps(build))
    return tree


#: A repository address given in the configuration (the default is none).
REPOSITORY = "https://example.org/turntable"


def test_pdf_names_the_commit_that_built_it_and_links_the_scripts(paper_tree: Path) -> None:
    import typst

    main = str(paper_tree / "paper" / "paper.typ")
    built = json.loads(
        typst.query(main, "<built-from>", field="value", one=True, root=str(paper_tree))
    )
    assert built == {"commit": BUILT_FROM, "dirty": True}
    links = set(json.loads(typst.query(main, "link", field="dest", root=str(paper_tree))))
    for stem in sorted(p.stem for p in (ROOT / "scripts").glob("fig*.py")):
        linked = f"{REPOSITORY}/blob/{BUILT_FROM}/scripts/{stem}.py" in links
        assert linked != (stem in NOT_YET_IN_ARTICLE), stem
    # without an address (the default: the project has none it can confirm), no link at all
    assert full_config()["paper"]["repository"] == ""
    build_json = paper_tree / "results" / "build.json"
    build = json.loads(build_json.read_text())
    build_json.write_text(json.dumps(build | {"repository": ""}))
    try:
        links = json.loads(typst.query(main, "link", field="dest", root=str(paper_tree)))
    finally:
        build_json.write_text(json.dumps(build))
    assert not [x for x in links if "/blob/" in x or x == ""], links


def test_pdf_says_when_the_claims_record_is_of_another_commit(paper_tree: Path) -> None:
    """The claims record (attached, the source of every number) names its own commit; the
    article says so when that is not the commit that built the PDF, and not otherwise."""
    import typst

    def text() -> str:
        main = str(paper_tree / "paper" / "paper.typ")
        return " ".join(typst.compile(main, root=str(paper_tree), format="html").decode().split())

    note = "The claims record was computed at another commit"
    assert note in text()  # the fixture's build.json names a made-up commit
    path = paper_tree / "results" / "claims.json"
    record = json.loads(path.read_text())
    same = {"git_commit": BUILT_FROM, "git_dirty": True}
    path.write_text(json.dumps(record | {"provenance": record["provenance"] | same}))
    try:
        assert note not in text()
    finally:
        path.write_text(json.dumps(record))


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


def test_article_body_fits_eight_pages_and_the_whole_twelve(paper_tree: Path) -> None:
    """The body (up to the references, label <body-end>) takes at most eight pages; with the
    appendix of claims, at most twelve."""
    import typst

    main = str(paper_tree / "paper" / "paper.typ")

    def page(label: str) -> int:
        return json.loads(typst.query(main, label, field="value", one=True, root=str(paper_tree)))

    body, pages = page("<body-end>"), page("<last-page>")
    assert body <= 8
    assert body < pages <= 12


# The fit of the synthetic film in the workflow (turntable fit) -------------------------------


def test_workflow_fits_the_synthetic_film_with_the_command(
    clean_build: Path,
) -> None:
    """Rule synthetic_film writes a film marked SYNTHETIC with its truth (config sections
    film and synthetic_film); rule fit_film runs `turntable fit` on it: the JSON selects the
    true model and recovers the coefficient within 4 standard errors."""
    import yaml

    workflow_build = clean_build
    config = full_config(yaml.safe_load((workflow_build / "config" / "config.yaml").read_text()))
    (truth,) = [f for f in config["synthetic_film"]["films"] if f["name"] == "slipping"]
    text = (workflow_build / "results/film/slipping.csv").read_text()
    assert text.startswith("# SYNTHETIC DATA")
    assert f"mu0 = {truth['coefficient']!r}" in text
    rig = film.rig_from_config(config["film"])
    data = film.read_film(workflow_build / "results/film/slipping.csv")
    assert data.t.size == round(rig.camera.duration * rig.camera.fps) + 1
    out = json.loads((workflow_build / "results/film/slipping.json").read_text())
    assert out["data"]["synthetic"] is True  # read from the SYNTHETIC header
    assert out["selected"] == truth["model"]
    assert out["selection"]["decisive"] is True
    assert out["warnings"] == []
    # the command's stderr (its warnings) goes to the job's log: none for these films
    assert (workflow_build / "logs/fit_film/slipping.log").read_text() == ""
    record = json.loads((workflow_build / "results/film/synthetic.json").read_text())
    assert record["synthetic"] is True
    assert record["films"]["slipping"]["coefficient"] == truth["coefficient"]
    assert abs(out["slipping"]["mu0"] - truth["coefficient"]) < 4 * out["slipping"]["mu0_stderr"]
    assert out["setup"]["omega_rad_s"] == pytest.approx(rig.setup.omega)
    assert out["setup"]["mass_kg"] == config["film"]["mass_kg"]
    assert out["slipping"]["mu0_dim_kg_per_s"] == pytest.approx(
        out["slipping"]["mu0"] * config["film"]["mass_kg"] * rig.setup.omega
    )


def test_report_page_of_the_films(clean_build: Path) -> None:
    """results/film.html, the page "What a film can tell" of the report: both figures
    embedded, the films marked SYNTHETIC, and the numbers of the JSON files (the fitted
    coefficient as "value ± stderr", the limit of the camera)."""
    page = (clean_build / "results" / "film.html").read_text(encoding="utf-8")
    assert page.count("data:image/png;base64,") == 2
    assert "What a film can tell" in page
    out = json.loads((clean_build / "results/film/slipping.json").read_text())
    text = fitplot.coefficient_text(out["slipping"], "mu0")
    assert "±" in text
    assert "<b>slipping</b> (SYNTHETIC)</td><td>slipping, &mu;<sub>0</sub> = " in page
    assert text in page
    measure = json.loads((clean_build / "results/film/measurability.json").read_text())
    assert f"below {measure['indistinguishable_above_mu0']:.3g}" in page


# The report's gallery -------------------------------------------------------------------------


@pytest.fixture(scope="module")
def gallery(clean_build: Path) -> tuple[str, Path]:
    """results/figures.html of the shared build."""
    return (clean_build / "results" / "figures.html").read_text(encoding="utf-8"), clean_build


def test_every_figure_with_its_caption(gallery) -> None:
    page, workdir = gallery
    figures = re.findall(r'<figure id="([^"]+)">(.*?)</figure>', page, re.S)
    # the animation first, shown (the report's own viewer only offers a GIF for download)
    assert [name for name, _ in figures] == ["animation", *NAMES]
    config = full_config(yaml.safe_load((workdir / "config" / "config.yaml").read_text()))
    for name, body in figures:
        image, mime = (
            ("animation.gif", "image/gif") if name == "animation" else (f"{name}.png", "image/png")
        )
        data = base64.b64encode((workdir / "figures" / image).read_bytes()).decode()
        assert f'src="data:{mime};base64,{data}"' in body, name
        caption = body.split("<figcaption>", 1)[1]
        assert "{{" not in caption
        assert len(re.sub(r"<[^>]+>", "", caption)) > 100, name
    # the captions' templates are filled from the configuration
    fig4 = dict(figures)["fig4_trajectories"]
    text = re.sub(r"<[^>]+>", "", fig4.split("<figcaption>", 1)[1])
    for m in config["fig4_trajectories"]["mu0"]:
        assert str(m) in text, m


# The plan for a cluster (profiles/slurm) ------------------------------------------------------


def test_one_job_per_k_with_the_slurm_profile(build_record: tuple[Path, dict]) -> None:
    """Planning the workflow with profiles/slurm: one study_k job per k, with the profile's
    default resources (the executor is swapped for the dry-run one, so no plugin is needed).
    """
    _, record = build_record
    plan = record["plan"]
    assert record["plan_returncode"] == 0, plan
    config = full_config(CONFIG)
    profile = yaml.safe_load((ROOT / "profiles/slurm/config.yaml").read_text())
    assert profile["executor"] == "slurm"
    counts = job_counts(plan)
    assert counts["study_k"] == len(config["study"]["k"])
    assert counts["study"] == 1
    for k in config["study"]["k"]:
        assert f"results/study/k_{k:.6g}.json" in plan
    jobs = plan.split("\nrule ")[1:]
    study_jobs = [job for job in jobs if job.startswith("study_k:")]
    assert len(study_jobs) == len(config["study"]["k"])
    runtime = profile["default-resources"]["runtime"]
    assert all(f"runtime={runtime}," in job for job in study_jobs)
    claims_runtime = profile["set-resources"]["claims"]["runtime"]
    assert [f"runtime={claims_runtime}," in j for j in jobs if j.startswith("claims:")] == [True]
