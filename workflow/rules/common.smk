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


def sources(folder):
    """Every file under `folder` of the repository (found by glob: a new module is included),
    as paths from source(), compiled Python left out.
    """
    root = ROOT
    return sorted(
        source(p.relative_to(root))
        for p in Path(root, folder).rglob("*")
        if p.is_file() and "__pycache__" not in p.parts
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
