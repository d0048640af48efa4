"""Shared set-up of the figure scripts: log redirection, matplotlib style, fixed-margin
figures, atomic saving.

The figure scripts run under Snakemake's ``script:`` directive, which puts the directory
of the scripts on ``sys.path``, so they import this package as ``_style``.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from turntable._atomic import replacing

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


def subplots(
    nrows: int,
    ncols: int,
    size: tuple[float, float],
    margins: tuple[float, float, float, float] = (0.5, 0.1, 0.4, 0.25),
    gaps: tuple[float, float] = (0.5, 0.5),
    **kwargs: Any,
) -> tuple[Figure, np.ndarray]:
    """Return a figure of `size` inches with an nrows x ncols grid of axes.

    The margins and gaps are fixed in inches instead of being computed by a layout
    engine, which would lay out every tick label once more (about 1 s per figure).

    Parameters
    ----------
    nrows, ncols : int
        Shape of the grid of axes.
    size : (float, float)
        Width and height of the figure in inches.
    margins : (float, float, float, float)
        Space left, right, below and above the grid, in inches.
    gaps : (float, float)
        Horizontal and vertical space between neighbouring axes, in inches.
    **kwargs
        Passed to `matplotlib.pyplot.subplots` (e.g. ``sharey``).

    Returns
    -------
    fig : matplotlib.figure.Figure
    axes : numpy.ndarray of matplotlib.axes.Axes
        Always two-dimensional, shape (nrows, ncols).
    """
    width, height = size
    left, right, bottom, top = margins
    axis_w = (width - left - right - (ncols - 1) * gaps[0]) / ncols
    axis_h = (height - bottom - top - (nrows - 1) * gaps[1]) / nrows
    fig, axes = plt.subplots(nrows, ncols, figsize=size, squeeze=False, **kwargs)
    fig.subplots_adjust(
        left=left / width,
        right=1.0 - right / width,
        bottom=bottom / height,
        top=1.0 - top / height,
        wspace=gaps[0] / axis_w,
        hspace=gaps[1] / axis_h,
    )
    return fig, axes


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
    for fmt in ("pdf", "png"):
        with replacing(snakemake.output[fmt]) as tmp:
            fig.savefig(tmp, format=fmt, dpi=snakemake.params.dpi, metadata=_METADATA[fmt])
    print(f"wrote {snakemake.output.pdf} and {snakemake.output.png}")
