# Configuration checks that the JSON schema cannot express, and paths shared by the rules.
from pathlib import Path

from snakemake.exceptions import WorkflowError

# Shared plotting module and matplotlib style: inputs of every figure rule, so that editing
# either rebuilds the figures.
STYLE_FILES = [
    str(Path(workflow.basedir) / "scripts" / "_style" / "__init__.py"),
    str(Path(workflow.basedir) / "scripts" / "_style" / "turntable.mplstyle"),
]


def _pairs(value):
    """Yield (suffix, pair) for a [start, end] pair or a list of such pairs."""
    if value and isinstance(value[0], list):
        for i, pair in enumerate(value):
            yield f"[{i}]", pair
    else:
        yield "", value


def check_config(config):
    """Raise WorkflowError unless every *_span and *_range pair is increasing.

    Each top-level section of the configuration is named after the rule that reads it, so
    the message names both the key and the rule. Also checks that fig4_trajectories gives
    one time span per value of mu0.
    """
    for rule_name, section in config.items():
        for key, value in section.items():
            if not key.endswith(("_span", "_range")):
                continue
            for suffix, (start, end) in _pairs(value):
                if not start < end:
                    raise WorkflowError(
                        f"Invalid configuration: {rule_name}.{key}{suffix} = [{start}, {end}] "
                        f"must end after it starts (start < end); "
                        f"used by rule {rule_name}."
                    )
    fig4 = config["fig4_trajectories"]
    if len(fig4["t_span"]) != len(fig4["mu0"]):
        raise WorkflowError(
            f"Invalid configuration: fig4_trajectories.t_span has {len(fig4['t_span'])} "
            f"entries but fig4_trajectories.mu0 has {len(fig4['mu0'])}; one time span per "
            f"mu0 is needed by rule fig4_trajectories."
        )
