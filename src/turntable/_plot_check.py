"""The check of a ``--plot FIG`` option before any work is done (``turntable fit``, ``track``)."""

from __future__ import annotations

import os
import sys
from pathlib import Path


def check_plot(path: str, prog: str) -> None:
    """Exit with status 2 and one line unless matplotlib can write ``path``."""

    def fail(message: str) -> None:
        print(f"{prog}: error: {message}", file=sys.stderr)
        raise SystemExit(2)

    try:
        from matplotlib.backend_bases import FigureCanvasBase
    except ImportError:
        fail("--plot needs matplotlib, which cannot be imported (pip install matplotlib)")
    formats = FigureCanvasBase.get_supported_filetypes()
    suffix = Path(path).suffix.lstrip(".").lower()
    if suffix not in formats:
        fail(f"--plot {path}: unknown format {suffix!r} (use one of {', '.join(sorted(formats))})")
    folder = Path(path).resolve().parent
    if not folder.is_dir() or not os.access(folder, os.W_OK):
        fail(f"--plot: cannot write into the folder {folder}")
