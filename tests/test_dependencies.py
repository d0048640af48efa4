"""The workflow reruns exactly what a change touches, and nothing when the tree moves.

On copies of the clean build of everything (tests/test_pipeline.py: the sources copied into a
temporary directory, the configuration cut down), one thing is changed and a dry run of the
default target tells which jobs Snakemake would run: every job whose script imports the
package after an edit of the package, only the jobs of a script (and those that read its
outputs) after an edit of that script, nothing after a copy of the whole tree. One test per
row of the table in README.md, "Changing a parameter and rebuilding only what changed".
The inputs of every job are checked against what its script imports, found by the standard
library's modulefinder (not by the workflow's own reading of the imports).
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import zlib
from modulefinder import ModuleFinder
from pathlib import Path

import pytest
import yaml

from ci_build import (
    FIGURE_NAMES,
    ROOT,
    SNAKEMAKE,
    base_config,
    job_counts,
    shared_build,
    write_config,
)
from test_pipeline import clean_build, in_project, shared_tmp  # noqa: F401
from test_provenance import _git as git

DRAWING = {*FIGURE_NAMES, "study", "animation"}  # the jobs that use scripts/_style
# the one figure whose script does not import turntable
NOT_IMPORTING_THE_PACKAGE = {"fig1_schematic"}
DOWNSTREAM_OF_FIGURES = {"paper", "figure_gallery", "all"}
# the page of the report that shows the film figures (Figs. 8 and 9) and the fits
FILM_PAGE = {"film_page"}
# the jobs of the synthetic films: the films, their fits (one job each), the figure of fits
FILMS = {"synthetic_film", "fit_film", "fig9_fit"} | FILM_PAGE


def plan(workdir: Path) -> dict[str, int]:
    """The jobs a dry run of the default target would run: {rule: count}."""
    proc = in_project(workdir, "--dry-run", cores=1)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    if "Nothing to be done" in proc.stdout + proc.stderr:
        return {}
    return job_counts(proc.stdout)


@pytest.fixture
def copy(clean_build: Path, tmp_path: Path) -> Path:  # noqa: F811
    """A copy of the clean build, sources and outputs, with their times (like cp -a)."""
    return Path(shutil.copytree(clean_build, tmp_path / "moved", symlinks=True))


@pytest.fixture(scope="module")
def everything(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> dict[str, int]:
    """Every job of the default target: the plan of the project from nothing (tests/ci_build.py),
    with the one value of k of the cut-down configuration."""
    _, record = shared_build(tmp_path_factory, worker_id)
    assert record["plan_returncode"] == 0, record["plan"]
    return job_counts(record["plan"]) | {"study_k": len(base_config()["study"]["k"])}


def test_a_build_and_a_copy_of_it_leave_nothing_to_do(copy: Path) -> None:
    """Inputs are recorded relative to the working directory: moving the tree changes none
    (and so a dry run on the copy shows that the build itself left nothing to do)."""
    assert plan(copy) == {}


def test_a_copy_run_with_the_original_package_stops_before_any_job(copy: Path) -> None:
    """A tree copied with its .venv runs the original's package (the editable install points
    at the original src/): the Snakefile refuses, naming both trees, before any job. The
    project's .venv run on the copy without PYTHONPATH is exactly that case."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    outputs = {p: p.stat().st_mtime_ns for p in (copy / "figures").iterdir()}
    proc = subprocess.run(
        [SNAKEMAKE, "--cores", "1", "--forcerun", "fig1_schematic"],
        cwd=copy,
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )
    out = proc.stdout + proc.stderr
    assert proc.returncode != 0, out
    assert f"Python imports turntable from {ROOT / 'src' / 'turntable'}, not from" in out
    assert f"belongs to {ROOT}" in out
    assert f"`rm -rf .venv && make` in {copy}" in out
    assert len(out.strip().splitlines()) <= 5, out
    assert {p: p.stat().st_mtime_ns for p in (copy / "figures").iterdir()} == outputs


@pytest.mark.parametrize("edit", ["append a comment", "add a module"])
def test_editing_the_package_reruns_every_job_that_imports_it(
    copy: Path, everything: dict[str, int], edit: str
) -> None:
    package = copy / "src" / "turntable"
    if edit == "append a comment":
        with open(package / "spectrum.py", "a") as f:
            f.write("# an edit\n")
    else:
        (package / "new_module.py").write_text('"""A new module."""\n')
    # every job but the schematic: each imports turntable, or reads what such a job wrote
    expected = {rule: n for rule, n in everything.items() if rule not in NOT_IMPORTING_THE_PACKAGE}
    assert plan(copy) == expected


def test_files_an_editor_leaves_in_the_package_rerun_nothing(copy: Path) -> None:
    """Hidden files and backups are not sources (a new module is: see above)."""
    for name in [".spectrum.py.swp", "spectrum.py~", "#spectrum.py#", ".mypy_cache/x.py", "a.orig"]:
        path = copy / "src" / "turntable" / name
        path.parent.mkdir(exist_ok=True)
        path.write_text("an editor's file\n")
    assert plan(copy) == {}


def test_editing_the_notebook_driver_reruns_every_job_that_runs_a_script(
    copy: Path, everything: dict[str, int]
) -> None:
    """Each script of scripts/ runs through workflow/scripts/run_notebook.py: all of those
    jobs rerun, and those that read what they wrote (claims_table, fit_film, figure_gallery),
    which is every job."""
    with open(copy / "workflow" / "scripts" / "run_notebook.py", "a") as f:
        f.write("\n# an edit\n")
    assert plan(copy) == everything


@pytest.mark.parametrize("how", ["touch", "rewrite unchanged"])
def test_a_notebook_driver_of_the_same_content_reruns_nothing(copy: Path, how: str) -> None:
    """The driver is an input, compared by content (the rule's `script:` is a stub that does
    not change): touching it, or a git checkout or stash that writes the same bytes, reruns
    nothing."""
    driver = copy / "workflow" / "scripts" / "run_notebook.py"
    if how == "touch":
        driver.touch()
    else:
        text = driver.read_bytes()
        driver.unlink()
        driver.write_bytes(text)
    assert plan(copy) == {}


def test_editing_a_caption_reruns_only_the_figure_page(copy: Path) -> None:
    with open(copy / "workflow" / "report" / "fig2_spectrum.rst", "a") as f:
        f.write("\nAn edit.\n")
    assert set(plan(copy)) == {"figure_gallery", "all"}


@pytest.mark.parametrize(
    ("script", "expected"),
    [
        ("scripts/fig2_spectrum.py", {"fig2_spectrum"} | DOWNSTREAM_OF_FIGURES),
        ("scripts/study_k.py", {"study_k", "study", "all"}),
        ("scripts/claims_report.py", {"claims", "claims_table", "paper", "all"}),
        ("scripts/_style/turntable.mplstyle", DRAWING | DOWNSTREAM_OF_FIGURES | FILM_PAGE),
        ("scripts/_style/__init__.py", DRAWING | DOWNSTREAM_OF_FIGURES | FILM_PAGE),
        # only the animation imports it; the figure page shows the animation
        ("scripts/_style/animation.py", {"animation", "figure_gallery", "all"}),
        ("workflow/scripts/report_figure.py", {"figure_gallery", "all"} | FILM_PAGE),
    ],
)
def test_editing_a_script_reruns_only_its_jobs(copy: Path, script: str, expected: set) -> None:
    with open(copy / script, "a") as f:
        f.write("\n# an edit\n" if script.endswith(".py") else "\n")
    planned = plan(copy)
    assert set(planned) == expected
    if "study_k" in expected:
        assert planned["study_k"] == len(base_config()["study"]["k"])  # one job per k


@pytest.mark.parametrize(
    ("section", "key", "expected"),
    [
        ("fig4_trajectories", "mu0", {"fig4_trajectories"} | DOWNSTREAM_OF_FIGURES),
        ("style", "dpi", {*FIGURE_NAMES, "study"} | DOWNSTREAM_OF_FIGURES | FILM_PAGE),
        ("film", "noise_m", FILMS | {"fig8_measurability"} | DOWNSTREAM_OF_FIGURES),
        ("synthetic_film", "films", FILMS | DOWNSTREAM_OF_FIGURES),
    ],
)
def test_editing_a_parameter_reruns_the_jobs_that_read_it(
    copy: Path, section: str, key: str, expected: set
) -> None:
    config = yaml.safe_load((copy / "config" / "config.yaml").read_text())
    value = config[section][key]
    if key == "films":  # another seed of the noise of the first film
        value[0]["seed"] += 1
    else:
        scaled = [v * 1.1 for v in value] if isinstance(value, list) else value * 1.1
        config[section][key] = value + 1 if isinstance(value, int) else scaled
    write_config(copy, config)
    planned = plan(copy)
    assert set(planned) == expected
    if "fit_film" in expected:  # one fit per film, each of whose data changed
        assert planned["fit_film"] == len(config["synthetic_film"]["films"])


# --------------------------------------------------------------------------- exact inputs
def jobs_of(plan_text: str) -> list[tuple[str, list[str]]]:
    """(rule, inputs) of every job a dry run lists."""
    jobs = []
    for block in re.split(r"^(?:local)?rule ", plan_text, flags=re.MULTILINE)[1:]:
        rule = block.split(":", 1)[0]
        found = re.search(r"^    input: (.*)$", block, flags=re.MULTILINE)
        jobs.append((rule, found.group(1).split(", ") if found else []))
    return jobs


def rule_scripts() -> dict[str, str]:
    """The rules whose `script:` is a file named in the rules files (workflow/scripts/), by
    rule: the path of the script relative to the repository."""
    found = {}
    for smk in (ROOT / "workflow" / "rules").glob("*.smk"):
        pattern = r'^rule (\w+):\n(?:(?!rule ).*\n)*?    script:\n        "\.\./(.+)"$'
        for rule, path in re.findall(pattern, smk.read_text(), flags=re.MULTILINE):
            found[rule] = f"workflow/{path}"
    return found


def imported_code(tree: Path, script: str) -> set[str]:
    """The files of `tree` that `script` imports, by modulefinder on the script's folder and
    src/ alone (the installed packages are not searched): every file of the package when any
    module of turntable is found, the file of any other module found (and for a package the
    files of its folder that are not Python: the style sheet of scripts/_style)."""
    path = tree / script
    finder = ModuleFinder(path=[str(path.parent), str(tree / "src")])
    finder.run_script(str(path))
    files = set()
    for name, module in finder.modules.items():
        if name == "__main__" or not module.__file__:
            continue
        if name.split(".")[0] == "turntable":
            package = tree / "src" / "turntable"
            files |= {p for p in package.rglob("*") if p.is_file() and "__pycache__" not in p.parts}
            continue
        file = Path(module.__file__)
        files.add(file)
        if file.name == "__init__.py":
            files |= {p for p in file.parent.iterdir() if p.is_file() and p.suffix != ".py"}
    return {str(p.relative_to(tree)) for p in files}


CODE_FOLDERS = ("src/turntable/", "scripts/_style/", "workflow/scripts/")
NOTEBOOK_DRIVER = "workflow/scripts/run_notebook.py"


def test_every_job_lists_exactly_the_code_its_script_imports(clean_build: Path) -> None:  # noqa: F811
    """For every job of a forced dry run: the files of the project's code among its inputs are
    exactly those its script imports (and the notebook driver for a script of scripts/), so
    that no edit reruns a job that does not run the file, and every edit reruns those that do.
    `turntable fit` (rule fit_film, a command) runs the package."""
    proc = in_project(clean_build, "--dry-run", "--forceall", "--nolock", cores=1)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    scripts = rule_scripts()
    assert set(scripts) == {"claims_table", "figure_gallery", "film_page"}
    package = imported_code(clean_build, "workflow/scripts/claims_table.py")
    checked = set()
    for rule, inputs in jobs_of(proc.stdout):
        code = {f for f in inputs if f.startswith(CODE_FOLDERS)}
        own = [f for f in inputs if re.fullmatch(r"scripts/\w+\.py", f)]
        if own:  # a script of scripts/, run as a notebook by the driver
            (script,) = own
            expected = imported_code(clean_build, script) | {NOTEBOOK_DRIVER}
        elif rule in scripts:
            expected = imported_code(clean_build, scripts[rule])
        elif rule == "fit_film":
            expected = package
        else:  # rules that copy or gather files
            assert rule in {"all"}, rule
            expected = set()
        assert code == expected, (rule, sorted(code ^ expected))
        checked.add(rule)
    assert {*FIGURE_NAMES, "animation", "study", "study_k", *scripts} <= checked
    # what a wrong declaration would look like: the schematic does not import turntable, and
    # only the animation imports scripts/_style/animation.py
    assert not any(
        f.startswith("src/") for f in imported_code(clean_build, "scripts/fig1_schematic.py")
    )
    assert "scripts/_style/animation.py" in imported_code(clean_build, "scripts/animation.py")


def test_values_of_ones_own_over_the_configuration_rerun_the_jobs_that_read_them(
    copy: Path,
) -> None:
    """The README's example: the last mu0 of Fig. 4 changed in a file of one's own, passed
    with --configfile (`make CONFIGFILE=my.yaml`), config/config.yaml left as it is: the
    jobs that read it are planned, as after an edit of config/config.yaml."""
    config = yaml.safe_load((copy / "config" / "config.yaml").read_text())
    mu0 = config["fig4_trajectories"]["mu0"]
    (copy / "my.yaml").write_text(yaml.safe_dump({"fig4_trajectories": {"mu0": [*mu0[:-1], 5.0]}}))
    proc = in_project(copy, "--dry-run", "--configfile", "my.yaml", cores=1)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert set(job_counts(proc.stdout)) == {"fig4_trajectories"} | DOWNSTREAM_OF_FIGURES


# --------------------------------------------------------------------------- the commit


def attached_build_record(pdf: Path) -> dict:
    """The build record the article carries as an attachment (build.json), read from the
    PDF's streams."""
    data = pdf.read_bytes()
    for start in re.finditer(rb"(?<!end)stream\r?\n", data):
        chunk = data[start.end() : data.index(b"endstream", start.end())]
        try:
            text = zlib.decompress(chunk)
        except zlib.error:
            text = chunk
        if text.lstrip().startswith(b"{") and b'"git_commit"' in text:
            record = json.loads(text)
            if {"provenance", "repository"} <= set(record):  # not claims.json, also attached
                return record
    raise AssertionError(f"{pdf} carries no build record")


def test_the_article_names_the_commit_and_the_dirty_tree_that_built_it(copy: Path) -> None:
    """The commit and the dirty state are params of rule paper: in a git checkout of a built
    tree, a new commit that touches none of the article's inputs reruns the article alone, as
    do uncommitted changes, and the article built carries the commit and the dirty mark."""
    (copy / ".gitignore").write_text(
        "figures/\nresults/\nlogs/\n.snakemake/\npaper/paper.pdf\n__pycache__/\n"
    )
    git(copy, "init", "-q")
    git(copy, "add", ".")
    git(copy, "commit", "-q", "-m", "the sources")
    pdf = copy / "paper" / "paper.pdf"
    article_alone = {"paper": 1, "all": 1}

    def build() -> dict:
        proc = in_project(copy, cores=1)
        assert proc.returncode == 0, proc.stdout + proc.stderr
        assert job_counts(proc.stderr + proc.stdout) == article_alone
        assert plan(copy) == {}
        return attached_build_record(pdf)["provenance"]

    assert plan(copy) == article_alone  # built outside git: the commit was "unknown"
    record = build()
    assert (record["git_commit"], record["git_dirty"]) == (git(copy, "rev-parse", "HEAD"), False)
    (copy / "NOTES.md").write_text("a note\n")
    git(copy, "add", "NOTES.md")
    git(copy, "commit", "-q", "-m", "a note")
    assert plan(copy) == article_alone  # a new commit
    (copy / "NOTES.md").write_text("a note, changed\n")
    assert plan(copy) == article_alone  # and a dirty tree
    record = build()
    head = git(copy, "rev-parse", "HEAD")
    assert (record["git_commit"], record["git_dirty"]) == (head, True)
    # the caption links name the commit too
    assert f"/blob/{head}/scripts/fig4_trajectories.py".encode() in pdf.read_bytes()


def test_the_article_names_the_values_of_its_own_configuration(copy: Path) -> None:
    """Values passed over config/config.yaml (make CONFIGFILE=...) are a param of rule paper:
    building with them reruns the article, whose build record (which paper/provenance.typ
    prints on the first page and in the section "Software") lists them; building again
    without them reruns it once more, with none listed."""
    own = copy / "local" / "my.yaml"
    own.parent.mkdir()
    own.write_text(yaml.safe_dump({"paper": {"timestamp": 1767225600}}))
    pdf = copy / "paper" / "paper.pdf"

    def build(*args: str) -> list[str]:
        proc = in_project(copy, *args, cores=1)
        assert proc.returncode == 0, proc.stdout + proc.stderr
        assert job_counts(proc.stderr + proc.stdout) == {"paper": 1, "all": 1}
        return attached_build_record(pdf)["config_overrides"]

    assert build("--configfile", "local/my.yaml") == ["paper.timestamp = 1767225600"]
    assert build() == []
