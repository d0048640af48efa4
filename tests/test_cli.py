"""The conventions of the ``turntable`` command: --version, -q and -v through `logging`,
progress bars on a terminal only, --json, shell completion (shtab)."""

from __future__ import annotations

import fcntl
import io
import json
import logging
import os
import pty
import shutil
import struct
import subprocess
import sys
import termios
import tomllib
from pathlib import Path

import pytest

from cli_here import run_here as run_turntable
from turntable import _terminal
from turntable.film import EXAMPLE_FILM
from turntable.fitting import InputError, fit_file

ROOT = Path(__file__).resolve().parents[1]
COMMAND = str(Path(sys.executable).with_name("turntable"))
#: Five frames: fitted, too short for a selection, so a warning says why.
SHORT = "t,x,y\n0,0.05,0\n0.1,0.049,0.016\n0.2,0.046,0.031\n0.3,0.041,0.045\n0.4,0.034,0.057\n"


def run_here(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    res = run_turntable(capsys, *args)
    return res.returncode, res.stdout, res.stderr


@pytest.fixture
def short(tmp_path: Path) -> str:
    path = tmp_path / "short.csv"
    path.write_text(SHORT)
    return str(path)


def test_version_is_the_one_of_pyproject(capsys: pytest.CaptureFixture[str]) -> None:
    version = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["version"]
    assert run_here(capsys, "--version") == (0, f"turntable {version}\n", "")
    import turntable

    assert turntable.__version__ == version


@pytest.mark.parametrize("where", ["before", "after"])
def test_quiet_and_verbose(capsys: pytest.CaptureFixture[str], short: str, where: str) -> None:
    """Warnings by default, none with -q, INFO lines too with -v; before or after the
    subcommand."""

    def fit(*flags: str) -> tuple[int, str, str]:
        args = ["fit", short, "--radius", "0.005", "--rpm", "33.3"]
        return run_here(capsys, *(flags + tuple(args) if where == "before" else args + list(flags)))

    code, out, err = fit()
    assert code == 0
    assert "turntable fit: warning: no model selected" in err
    assert "info:" not in err
    code, quiet_out, quiet_err = fit("-q")
    assert (code, quiet_out, quiet_err) == (0, out, "")
    code, _, loud = fit("-v")
    assert "turntable fit: info: " in loud
    assert "turntable fit: warning: no model selected" in loud
    code, _, err = fit("-q", "-v")
    assert code == 2
    assert err.count("\n") == 1
    assert "not allowed with argument" in err


def test_the_library_logs_through_logging(tmp_path: Path, caplog: pytest.LogCaptureFixture) -> None:
    """fit_file prints nothing: a Tracker export's note is a log record, bad input an
    InputError of one line."""
    export = tmp_path / "tracker.txt"
    # The first 40 frames of the example film: fitted in a tenth of a second (a few frames of a
    # straight line send the fit looking for the bounds of its coefficients, for seconds).
    lines = [line for line in EXAMPLE_FILM.read_text().splitlines() if line[:1].isdigit()]
    export.write_text("mass A\nt,x,y\n" + "\n".join(lines[:40]) + "\n")
    with caplog.at_level(logging.WARNING, logger="turntable"):
        fit_file(export, 0.005, rpm=100 / 3)
    assert [r.name for r in caplog.records] == ["turntable.fitting"]
    assert "Tracker's track" in caplog.records[0].getMessage()
    with pytest.raises(InputError, match="--radius must be a finite number > 0") as info:
        fit_file(export, -1.0, rpm=33.3)
    assert "\n" not in str(info.value)


def test_the_fit_reports_its_progress(short: str) -> None:
    calls: list[tuple] = []
    fit_file(short, 0.005, rpm=33.3, progress=lambda *a: calls.append(a))
    assert calls == [("fitting", 0, 2), ("fitting", 1, 2), ("fitting", 2, 2)]


def test_bars_only_on_a_terminal(monkeypatch: pytest.MonkeyPatch) -> None:
    """A tqdm bar on stderr when it is a terminal and not -q; None otherwise."""

    class Terminal(io.StringIO):
        def isatty(self) -> bool:
            return True

    monkeypatch.setattr(sys, "stderr", io.StringIO())
    with _terminal.bars() as progress:
        assert progress is None
    terminal = Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    with _terminal.bars(quiet=True) as progress:
        assert progress is None
    with _terminal.bars() as progress:
        progress("tracking", 3, 10)
        assert "tracking:   0%" in terminal.getvalue()
        progress("fitting", 1, 2)
        with _terminal.logged("turntable fit"):
            logging.getLogger("turntable.fitting").warning("a note")
    assert "fitting:   0%" in terminal.getvalue()
    # the bar is cleared before a log line, which has a line of its own
    assert "\rturntable fit: warning: a note\n" in terminal.getvalue()


def _stderr_of(args: list[str], terminal: bool) -> str:
    """stderr of ``turntable ARGS`` in a separate process, on a terminal or on a pipe."""
    if not terminal:
        return subprocess.run(
            [COMMAND, *args], capture_output=True, text=True, timeout=120, check=True
        ).stderr
    main, sub = pty.openpty()
    fcntl.ioctl(sub, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 80, 0, 0))
    proc = subprocess.Popen([COMMAND, *args], stdout=subprocess.DEVNULL, stderr=sub)
    os.close(sub)
    chunks = []
    while True:
        try:
            chunk = os.read(main, 4096)
        except OSError:  # the terminal closed
            break
        if not chunk:
            break
        chunks.append(chunk)
    os.close(main)
    assert proc.wait(timeout=120) == 0
    return b"".join(chunks).decode()


def test_a_progress_bar_shows_on_a_terminal_and_nothing_extra_on_a_pipe(tmp_path: Path) -> None:
    # the first 40 frames of the example film: fitted in a tenth of a second, with no warning
    lines = [line for line in EXAMPLE_FILM.read_text().splitlines() if line[:1].isdigit()]
    film40 = tmp_path / "film.csv"
    film40.write_text("t,x,y\n" + "\n".join(lines[:40]) + "\n")
    args = ["fit", str(film40), "--radius", "0.005", "--rpm", "33.3333333"]
    assert "fitting:" in _stderr_of(args, terminal=True)
    assert _stderr_of(args, terminal=False) == ""
    assert _stderr_of(["-q", *args], terminal=True) == ""


def _claims_report() -> dict:
    claim = {
        "verdict": "confirmed",
        "expected": "confirmed",
        "decisive": "error",
        "reproduced": {"error": 1e-12, "other": 3},
        "tolerance": {"error": {"<": 1e-9}},
    }
    return {"order": ["a"], "claims": {"a": claim}, "summary": {"confirmed": 1}}


def test_claims_json(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "claims.json"
    path.write_text(json.dumps(_claims_report()))
    code, out, err = run_here(capsys, "claims", str(path), "--json")
    assert (code, err) == (0, "")
    assert json.loads(out) == {
        "summary": {"confirmed": 1},
        "claims": [
            {
                "id": "a",
                "verdict": "confirmed",
                "decisive": "error",
                "reproduced": 1e-12,
                "bound": {"<": 1e-9},
                "expected": "confirmed",
            }
        ],
    }
    broken = _claims_report()
    del broken["claims"]["a"]["decisive"]
    path.write_text(json.dumps(broken))
    code, out, err = run_here(capsys, "claims", str(path), "--json")
    assert (code, out, err.count("\n")) == (2, "", 1)
    assert "not a claims report" in err


def test_print_completion(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    """A bash completion script that bash loads, knowing the commands and their options."""
    code, script, _ = run_here(capsys, "--print-completion", "bash")
    assert code == 0
    for word in ("fit", "track", "claims", "--radius", "--platter-radius", "--json", "--version"):
        assert word in script, word
    path = tmp_path / "turntable.bash"
    path.write_text(script)
    bash = shutil.which("bash")
    shown = subprocess.run(
        [bash, "-c", f"source {path} && complete -p turntable"],
        capture_output=True, text=True, check=True,
    )  # fmt: skip
    assert shown.stdout.startswith("complete ")
    code, _, err = run_here(capsys, "--print-completion", "fish")
    assert code == 2
    assert "invalid choice" in err
