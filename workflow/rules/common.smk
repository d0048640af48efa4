# The configuration, checked, and what the rules share: the figures, the code a job runs,
# the inputs of a job that runs a script of scripts/ (through Snakemake's script:).
import json
import os
from pathlib import Path

import turntable
import turntable._imports
import turntable.config
import yaml
from snakemake.exceptions import WorkflowError
from snakemake.io import apply_wildcards
from turntable.provenance import git_state

ROOT = Path(workflow.basedir).parent
if not Path(turntable.__file__).resolve().is_relative_to(ROOT / "src"):
    raise WorkflowError(
        f"Python imports turntable from {Path(turntable.__file__).parent}, not from "
        f"{ROOT / 'src'}: a copied or moved tree needs its own .venv (rm -rf .venv && make)."
    )


def _sorted(value):
    """`value` with the keys of every mapping sorted: params compare as data."""
    if isinstance(value, dict):
        return {key: _sorted(value[key]) for key in sorted(value)}
    return [_sorted(v) for v in value] if isinstance(value, list) else value


# Refuse a mistake before any job runs: one line per problem, the key and what is expected.
SCHEMA = Path(workflow.basedir, "schemas", "config.schema.yaml")
_problems = turntable.config.validate(config, SCHEMA) or turntable.config.problems(
    config
)
if _problems:
    raise WorkflowError(
        "Invalid configuration; nothing was run and no output was changed:\n"
        + "\n".join(_problems[:20])
    )
config.update(_sorted(config))
DEFAULTS = {}
turntable.config.validate(DEFAULTS, SCHEMA)

# The values of this run that differ from the defaults (section.key = value), and the
# commit and state of the tree: params of the article, which names them.
OVERRIDES = sorted(
    f"{section}.{key} = {json.dumps(value)}"
    for section, values in config.items()
    for key, value in values.items()
    if value != DEFAULTS[section][key]
)
_commit, _dirty = git_state(ROOT)
GIT_STATE = f"{_commit} (dirty)" if _dirty else _commit

FIGURES = yaml.safe_load(Path(workflow.basedir, "figures.yaml").read_text())
STYLE = ["scripts/_style/__init__.py", "scripts/_style/turntable.mplstyle"]


def code_inputs(*entries):
    """The package's files that the entries run (turntable._imports.code_of), as inputs."""
    return [str(p.relative_to(ROOT)) for p in turntable._imports.code_of(*entries)]


# `turntable ...` and `python -m turntable.campaign ...`: the code of a shell command's job.
CLI = code_inputs("turntable.cli")
CAMPAIGN_CODE = code_inputs("turntable.campaign")


def script_inputs(name, style=()):
    """Inputs of the job that runs scripts/<name>.py: the script and the code it runs."""
    script = f"scripts/{name}.py"
    return {"script": script, "code": [*code_inputs(ROOT / script), *style]}


def moved_outputs(job, folder):
    """Params function of a notebook (notebooks.smk): the outputs of `job` under `folder`."""

    def outputs(wildcards):
        def move(path):
            return os.path.join(
                apply_wildcards(folder, wildcards), apply_wildcards(path, wildcards)
            )

        return {
            key: list(map(move, value)) if isinstance(value, list) else move(value)
            for key, value in job.output.items()
        }

    return outputs
