"""``turntable ARGS`` run in the test's own process (`turntable.cli.main`), its output taken
from pytest's ``capsys``: the result a subprocess would give, without its start-up."""

from __future__ import annotations

import subprocess

import pytest

from turntable import cli


def run_here(capsys: pytest.CaptureFixture[str], *args: str) -> subprocess.CompletedProcess:
    """``turntable ARGS`` in this process, as exit status, stdout, stderr."""
    try:
        code = cli.main(list(args))
    except SystemExit as exc:
        code = exc.code
    out, err = capsys.readouterr()
    return subprocess.CompletedProcess(args, code, out, err)
