"""Where a result came from: the commit, a dirty tree, the Python and library versions.

One function, :func:`provenance`, makes the record that ``results/claims.json``,
``results/study/summary.json``, ``results/benchmarks.json`` and the article carry. Versions
are read from the installed distributions' metadata (``importlib.metadata``), so recording
them imports none of the tools: the package still needs only its runtime dependencies.
"""

from __future__ import annotations

import platform
import subprocess
from importlib import metadata
from pathlib import Path
from typing import Any

#: Distributions whose versions are recorded, in this order. ``None`` when not installed.
PACKAGES = ("numpy", "scipy", "mpmath", "sympy", "matplotlib", "snakemake", "typst")

#: The commit recorded outside a git checkout (or without git).
UNKNOWN = "unknown"


def _git(args: list[str], cwd: str | Path | None) -> str | None:
    """Output of ``git <args>`` in ``cwd``, or None if git is missing or fails."""
    try:
        out = subprocess.run(
            ["git", *args], cwd=cwd, capture_output=True, text=True, check=True, timeout=10
        )
    except (OSError, subprocess.SubprocessError):
        return None
    return out.stdout


def git_state(cwd: str | Path | None = None) -> tuple[str, bool | None]:
    """Return ``(commit, dirty)`` of the git checkout containing ``cwd``.

    ``commit`` is the full hash of ``HEAD`` (:data:`UNKNOWN` outside a checkout);
    ``dirty`` is True when ``git status --porcelain`` lists any change, tracked or
    untracked-but-not-ignored (generated outputs are ignored), and None when unknown.
    """
    head = _git(["rev-parse", "HEAD"], cwd)
    commit = head.strip() if head is not None else ""
    if len(commit) != 40:
        return UNKNOWN, None
    status = _git(["status", "--porcelain", "--untracked-files=normal"], cwd)
    return commit, (None if status is None else bool(status.strip()))


def package_versions(names: tuple[str, ...] = PACKAGES) -> dict[str, str | None]:
    """Installed version of each distribution in ``names`` (None if it is not installed)."""
    versions: dict[str, str | None] = {}
    for name in names:
        try:
            versions[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            versions[name] = None
    return versions


def provenance(cwd: str | Path | None = None) -> dict[str, Any]:
    """Return the provenance record of a result built now from the checkout at ``cwd``.

    Parameters
    ----------
    cwd : path, optional
        A folder inside the git checkout of the sources (default: the working directory).

    Returns
    -------
    dict
        ``git_commit`` (str), ``git_dirty`` (bool, or None when unknown), ``python``
        (e.g. ``"3.11.9"``), ``turntable`` (the package version) and ``packages``
        (distribution -> version or None, for every name in :data:`PACKAGES`).
    """
    from turntable import __version__

    commit, dirty = git_state(cwd)
    return {
        "git_commit": commit,
        "git_dirty": dirty,
        "python": platform.python_version(),
        "turntable": __version__,
        "packages": package_versions(),
    }
