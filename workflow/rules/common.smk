# Paths shared by the rules: the code every job depends on. (The configuration is checked by
# workflow/config_checks.py.)
import os
from pathlib import Path

# The root of the repository (the main Snakefile is workflow/Snakefile).
ROOT = Path(workflow.basedir).parent


def source(path):
    """A file of the repository (`path` relative to it), as a path relative to the working
    directory: the same string wherever the work tree is moved or copied, so that Snakemake's
    record of a job's inputs still matches. Also right with --directory elsewhere.
    """
    return os.path.relpath(ROOT / path)


# Files under a source folder that are not sources: compiled Python, and what editors and
# tools leave beside a file (vim's .name.swp, emacs's name~ and #name#, patch leftovers).
NOT_SOURCES = ("~", ".swp", ".swo", ".swx", ".bak", ".orig", ".rej", ".pyc", ".pyo")


def is_source(path, folder):
    """Whether `path`, a file under `folder`, is a source: not hidden (no part of it below
    `folder` starts with a dot: .name.swp, .mypy_cache/), not compiled, not a backup."""
    parts = path.relative_to(folder).parts
    return (
        path.is_file()
        and "__pycache__" not in parts
        and not any(part.startswith(".") for part in parts)
        and not path.name.endswith(NOT_SOURCES)
        and not (path.name.startswith("#") and path.name.endswith("#"))
    )


def sources(folder):
    """Every source file under `folder` of the repository (found by glob: a new module is
    included), as paths from source(); hidden files, editor backups and compiled Python
    left out (see is_source), so that opening a file in an editor reruns nothing.
    """
    top = Path(ROOT, folder)
    return sorted(
        source(p.relative_to(ROOT)) for p in top.rglob("*") if is_source(p, top)
    )


# The package: an input of every job whose script imports turntable, so that editing any
# file of src/turntable/ reruns every such job (and nothing else).
PACKAGE = sources("src/turntable")
# The shared plotting module and matplotlib style: inputs of every job that draws, so that
# editing them redraws every figure (and nothing else).
STYLE = sources("scripts/_style")

# Each script of scripts/ runs once per job, as a Jupyter notebook, through this driver
# (the rule's `script:`); the job writes the notebook with its outputs beside its other
# outputs. A rule gives the script as input `script`, the code it depends on as input
# `code`, and the notebook as output `notebook`: see notebook().
NOTEBOOK_DRIVER = "../scripts/run_notebook.py"
NOTEBOOKS = []


def notebook(name, **wildcards):
    """Output `notebook` of a job of scripts/<name>.py: results/notebooks/<name>.ipynb.

    `name` may hold wildcards; give their values (lists) as keywords, so that target
    `notebooks` lists every notebook.
    """
    path = f"results/notebooks/{name}.ipynb"
    NOTEBOOKS.extend(expand(path, **wildcards))
    return ensure(path, non_empty=True)


# What a figure of workflow/figures.yaml needs beyond the rule that figures.smk generates for
# it (its script, the package and the style as inputs; the PDF, the PNG and the notebook as
# outputs; its section of the configuration and the resolution as params), by figure name:
# {"input": {...}, "output": {...}, "params": {...}}, filled by the rules files included
# before figures.smk (film.smk).
FIGURE_EXTRAS = {}
# Figures that read the claims parameters (the script resolves them with their defaults):
# Fig. 6(b) draws the fit of limit.convergence, Fig. 7 marks the factor that "much faster"
# means (much_faster_factor).
FIGURE_EXTRAS["fig6_limit"] = {"params": {"claims": config["claims"]}}
FIGURE_EXTRAS["fig7_rolling_resistance"] = {"params": {"claims": config["claims"]}}


def _git_state():
    """(commit, dirty) of the checkout, by turntable.provenance.git_state, loaded from its
    file alone: importing the package would import numpy and scipy in every Snakemake run.
    """
    from importlib.util import module_from_spec, spec_from_file_location

    spec = spec_from_file_location("_provenance", ROOT / "src/turntable/provenance.py")
    provenance = module_from_spec(spec)
    spec.loader.exec_module(provenance)
    commit, dirty = provenance.git_state(ROOT)
    return f"{commit}{' (dirty)' if dirty else ''}"


# The commit of the checkout and whether its tree is dirty, as a param of the jobs that print
# them (the article): a new commit, or a tree that becomes dirty or clean, reruns them
# (Snakemake reruns a job whose params changed), so the commit printed is the one that
# built the output.
GIT_STATE = _git_state()
