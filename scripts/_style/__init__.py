"""Shared set-up of the figure scripts: log redirection, matplotlib style, atomic saving.

The figure scripts run under Snakemake's ``script:`` directive and import this package
after putting ``snakemake.scriptdir`` on ``sys.path``.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
from matplotlib.figure import Figure

STYLE = Path(__file__).with_name("turntable.mplstyle")

#: Figure widths in inches: one column, and the full page width.
SINGLE = 3.4
DOUBLE = 7.0

# Fixed metadata, so that two builds of a figure are byte-identical.
_METADATA = {
    "pdf": {"CreationDate": None, "ModDate": None, "Producer": "turntable", "Creator": None},
    "png": {"Software": None},
}


def setup(snakemake: Any) -> None:
    """Send stdout and stderr of the script to its log file and load the shared style.

    Parameters
    ----------
    snakemake : snakemake.script.Snakemake
        The object Snakemake passes to a ``script:``; its first ``log`` file is used.
    """
    log = open(snakemake.log[0], "w", buffering=1)  # noqa: SIM115 (lives as long as the job)
    sys.stdout = sys.stderr = log
    plt.style.use(STYLE)


def save(fig: Figure, snakemake: Any) -> None:
    """Write `fig` to the ``pdf`` and ``png`` outputs of the rule, each atomically.

    Each file is first written under a hidden temporary name in the same directory and
    then renamed, so an interrupted job never leaves a truncated figure under its final
    name.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The finished figure.
    snakemake : snakemake.script.Snakemake
        Supplies ``output.pdf``, ``output.png`` and ``params.dpi``.
    """
    engine = fig.get_layout_engine()
    if engine is not None:  # lay out once, not again for each file
        engine.execute(fig)
        fig.set_layout_engine("none")
    for fmt in ("pdf", "png"):
        path = Path(snakemake.output[fmt])
        tmp = path.with_name(f".{path.name}.partial")
        try:
            fig.savefig(tmp, format=fmt, dpi=snakemake.params.dpi, metadata=_METADATA[fmt])
            os.replace(tmp, path)
        finally:
            tmp.unlink(missing_ok=True)
    print(f"wrote {snakemake.output.pdf} and {snakemake.output.png}")
