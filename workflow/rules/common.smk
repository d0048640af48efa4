# Paths shared by the rules: the code every job depends on. (The configuration is checked by
# workflow/config_checks.py.)
import os
from pathlib import Path

# The project's files a script imports (workflow/code_inputs.py, read from the script's
# import statements): the input `code` of its job, so that editing a file reruns exactly the
# jobs whose script imports it. The package src/turntable/ counts as a whole (every file of
# it, found by glob: a new module counts too; hidden files and editor backups do not).
from code_inputs import code_inputs, package_sources

# The root of the repository (the main Snakefile is workflow/Snakefile).
ROOT = Path(workflow.basedir).parent


def source(path):
    """A file of the repository (`path` relative to it), as a path relative to the working
    directory: the same string wherever the work tree is moved or copied, so that Snakemake's
    record of a job's inputs still matches. Also right with --directory elsewhere.
    """
    return os.path.relpath(ROOT / path)


def code(script):
    """The files of the project that `script` (relative to the repository) imports, as paths
    from source(): the package's when it imports turntable, scripts/_style/ when it draws
    (scripts/_style/animation.py only for the animation), a helper of workflow/scripts/.
    """
    return [source(p) for p in code_inputs(script)]


# The package: an input of a job that runs it other than through a script (`turntable fit`).
PACKAGE = [source(p) for p in package_sources()]

# Each script of scripts/ runs once per job, as a Jupyter notebook, through the driver
# workflow/scripts/run_notebook.py; the job writes the notebook with its outputs beside its
# other outputs. The rule's `script:` is the stub NOTEBOOK_JOB, which runs the driver: the
# driver is an input, compared by content, so that touching it reruns nothing (Snakemake
# compares a `script:` by modification time alone). A rule takes its inputs `script`,
# `driver` and `code` from notebook_inputs() and its output `notebook` from notebook().
NOTEBOOK_JOB = "../scripts/notebook_job.py"
DRIVER = source("workflow/scripts/run_notebook.py")


def notebook_inputs(script):
    """Inputs of the job that runs `script` (scripts/<name>.py) as a notebook: the script,
    the driver, and the code the script imports."""
    return {"script": source(script), "driver": DRIVER, "code": code(script)}


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
# it (notebook_inputs() as inputs; the PDF, the PNG and the notebook as outputs; its section
# of the configuration and the resolution as params), by figure name: {"input": {...},
# "output": {...}, "params": {...}}, filled by the rules files included before figures.smk
# (film.smk).
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


def _config_overrides():
    """Every value of this run's configuration that differs from config/config.yaml, the
    project's reference values (what --configfile or --config changed), as
    "section.key = value" lines in JSON notation; empty for the reference configuration.
    """
    import json

    import yaml

    with open(ROOT / "config" / "config.yaml", encoding="utf-8") as f:
        reference = yaml.safe_load(f)
    changed = []
    for section, values in config.items():
        ref = reference.get(section) or {}
        for key, value in values.items() if isinstance(values, dict) else []:
            if key not in ref or json.dumps(value) != json.dumps(ref[key]):
                changed.append(f"{section}.{key} = {json.dumps(value)}")
    return sorted(changed)


# The values of this run that differ from the reference configuration, as a param of the
# article's job: the PDF says with which values it was built (a change reruns it).
CONFIG_OVERRIDES = _config_overrides()
