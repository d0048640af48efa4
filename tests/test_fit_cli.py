"""The ``turntable fit`` command (`turntable.cli`): output on files it has never seen, and
every kind of bad input (one line on stderr naming file, line and column, exit status 2).
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import turntable as tt
from ci_build import full_config
from cli_here import run_here as run_turntable
from turntable import cli, film, fit
from turntable._json import finite_or_none
from turntable.fit import plot as fitplot

ROOT = Path(__file__).resolve().parents[1]
COMMAND = str(Path(sys.executable).with_name("turntable"))
#: Prelude of a child interpreter in which matplotlib cannot be imported.
BLOCK = """
import sys
class Block:
    def find_spec(self, name, path=None, target=None):
        if name.split('.')[0] == 'matplotlib':
            raise ImportError('blocked ' + name)
sys.meta_path.insert(0, Block())
"""


def run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    """``turntable fit ARGS`` as a separate process (the installed console script)."""
    return subprocess.run(
        [COMMAND, "fit", *args], capture_output=True, text=True, timeout=120, cwd=cwd, check=False
    )


def run_here(capsys: pytest.CaptureFixture[str], *args: str) -> subprocess.CompletedProcess:
    """``turntable fit ARGS`` in this process, same result as `run`."""
    return run_turntable(capsys, "fit", *args)


# --------------------------------------------------------------------------- an unseen film
def _unseen_film(tmp_path: Path, model: str, entropy: int) -> tuple[Path, dict]:
    """A film from random parameters, written with comments, extra columns in another
    order, a clock that does not start at 0, and an axis away from the origin."""
    rng = np.random.default_rng(entropy)
    setup = film.Setup(
        radius=float(rng.uniform(3e-3, 1e-2)),
        omega=film.rpm_to_omega(float(rng.choice([100.0 / 3.0, 45.0, 78.0]))),
        k=float(rng.uniform(0.3, 0.7)),
        axis=(float(rng.uniform(-0.2, 0.2)), float(rng.uniform(-0.2, 0.2))),
    )
    c = float(np.exp(rng.uniform(*np.log([0.05, 5.0] if model == "slipping" else [0.003, 0.3]))))
    angle = rng.uniform(0, 2 * np.pi)
    position = np.asarray(setup.axis) + rng.uniform(0.03, 0.08) * np.array(
        [np.cos(angle), np.sin(angle)]
    )
    z0 = film.state_from_si(position, rng.uniform(-0.02, 0.02, 2), [0.0, 0.0], setup)
    if model == "rolling_resistance":
        z0 = tt.no_slip_state(z0, setup.k)
    camera = film.Camera(fps=float(rng.choice([60.0, 120.0])), noise=3e-4, duration=8.0)
    data = fit.simulate_film(model, c, z0, setup, camera, seed=int(rng.integers(2**31)))
    t0 = float(rng.uniform(0.0, 100.0))
    lines = ["# tracked positions", "frame,y,quality,t,x"]
    lines += [
        f"{i},{y:.12g},0.9,{t + t0:.12g},{x:.12g}"
        for i, (t, x, y) in enumerate(zip(data.t, data.x, data.y, strict=True))
    ]
    path = tmp_path / "unseen film.csv"
    path.write_text("\n".join(lines) + "\n")
    mass = float(rng.uniform(1e-3, 5e-2))
    truth = {"setup": setup, "c": c, "z0": z0, "noise": camera.noise, "t0": t0, "mass": mass}
    return path, truth


@pytest.mark.parametrize("model", fit.MODELS)
def test_fit_of_a_film_never_seen(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch, model: str
) -> None:
    """Random parameters each run (the seed is in the failure message)."""
    entropy = int(np.random.SeedSequence().entropy)
    path, truth = _unseen_film(tmp_path, model, entropy)
    setup = truth["setup"]
    monkeypatch.chdir(tmp_path)  # the file named as it is in the current directory
    proc = run_here(
        capsys,
        path.name,
        "--radius",
        repr(setup.radius),
        "--omega",
        repr(setup.omega),
        "--k",
        repr(setup.k),
        "--axis",
        repr(setup.axis[0]),
        repr(setup.axis[1]),
        "--mass",
        repr(truth["mass"]),
    )
    why = f"seed {entropy}: {proc.stderr}"
    assert proc.returncode == 0, why
    # warnings only, and none that says the given rate or axis is wrong (they are exact)
    for line in proc.stderr.splitlines():
        assert line.startswith("turntable fit: warning: "), why
        assert "neither model fits" not in line, why
        assert "the film prefers" not in line, why
    out = json.loads(proc.stdout)
    assert out["warnings"] == [
        line.removeprefix("turntable fit: warning: ") for line in proc.stderr.splitlines()
    ]
    assert out["data"]["synthetic"] is False  # no SYNTHETIC comment in the file
    assert out["consistency"]["freed"] == ["omega", "axis"]
    assert out["selected"] == model, why
    name = fit.COEFFICIENT[model]
    entry = out[model]
    assert abs(entry[name] - truth["c"]) < 5 * entry[f"{name}_stderr"], why
    assert entry["rms_residual_m"] == pytest.approx(truth["noise"], rel=0.15), why
    for key in ("mu0", "mu0_stderr", "rms_residual_m", "aic", "state0"):
        assert key in out["slipping"]
    for key in ("delta", "delta_stderr", "rms_residual_m", "aic", "state0"):
        assert key in out["rolling_resistance"]
    assert len(entry["state0"]) == 6
    # the initial state's position is the first frame's, relative to the axis, in R
    assert np.hypot(*(np.array(entry["state0"][:2]) - truth["z0"][:2])) < 0.2, why
    assert out["data"]["t0_s"] == pytest.approx(truth["t0"])
    assert out["data"]["file"] == path.name
    factor = truth["mass"] * setup.omega * (1.0 if model == "slipping" else setup.radius**2)
    unit = "kg_per_s" if model == "slipping" else "kg_m2_per_s"
    assert entry[f"{name}_dim_{unit}"] == pytest.approx(entry[name] * factor)
    lo, hi = entry[f"{name}_ci95"]
    assert lo < entry[name] < hi
    weights = out["selection"]["akaike_weights"]
    assert weights[model] > 0.5
    assert sum(weights.values()) == pytest.approx(1.0)
    other = next(m for m in fit.MODELS if m != model)
    assert out["selection"]["aicc_difference"] == pytest.approx(
        out[other]["aicc"] - out[model]["aicc"]
    )


def test_rpm_and_omega_agree_and_python_m_runs_the_same(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """--rpm 45 and the --omega of 45 rpm give the same fit; ``python -m turntable`` (a
    process of its own) runs the same command as `turntable.cli.main`."""
    path, truth = _unseen_film(tmp_path, "slipping", 5)
    common = ["--radius", repr(truth["setup"].radius), "--axis"]
    common += [repr(a) for a in truth["setup"].axis]
    a = run_here(capsys, str(path), *common, "--omega", repr(film.rpm_to_omega(45.0)))
    b = subprocess.run(
        [sys.executable, "-m", "turntable", "fit", str(path), *common, "--rpm", "45"],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert a.returncode == b.returncode == 0, a.stderr + b.stderr
    ja, jb = json.loads(a.stdout), json.loads(b.stdout)
    assert ja["setup"]["omega_rad_s"] == pytest.approx(jb["setup"]["omega_rad_s"])
    assert ja["slipping"]["mu0"] == pytest.approx(jb["slipping"]["mu0"], rel=1e-9)


def test_negative_numbers_in_scientific_notation_are_values() -> None:
    args = cli.parse_args(["fit", "f.csv", "--radius", "1e-2", "--axis", "-1e-05", "-2E-7"])
    assert args.axis == [-1e-05, -2e-7]
    with pytest.raises(SystemExit):
        cli.parse_args(["fit", "f.csv", "--radius", "1e-2", "--axis", "-1e-05", "-x"])


def test_plot(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path, truth = _unseen_film(tmp_path, "rolling_resistance", 6)
    figure = tmp_path / "fit.png"
    proc = run_here(
        capsys,
        str(path),
        "--radius",
        repr(truth["setup"].radius),
        "--omega",
        repr(truth["setup"].omega),
        "--axis",
        *[repr(a) for a in truth["setup"].axis],
        "--plot",
        str(figure),
    )
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["selected"] == "rolling_resistance"
    assert figure.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []
    # readable by everyone, as the films written by turntable.film.write_film
    assert figure.stat().st_mode & 0o777 == 0o644


def _blocked(*commands: list[str]) -> list[subprocess.CompletedProcess]:
    """Each command run by `turntable.cli.main` in one child interpreter in which matplotlib
    cannot be imported: (exit status, stdout, stderr) of each."""
    code = (
        BLOCK
        + f"""
import contextlib, io, json
from turntable.cli import main
results = []
for args in {[list(c) for c in commands]!r}:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(args)
        except SystemExit as exc:
            code = exc.code
    results.append([code, out.getvalue(), err.getvalue()])
sys.__stdout__.write(json.dumps(results))
"""
    )
    proc = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=False
    )
    assert proc.returncode == 0, proc.stderr
    results = json.loads(proc.stdout)
    return [subprocess.CompletedProcess(c, *r) for c, r in zip(commands, results, strict=True)]


def test_matplotlib_is_needed_only_for_plot(tmp_path: Path) -> None:
    path = _rig_file(tmp_path, "slipping", 3.0, film.Camera(30.0, 3e-4, 4.0), 0)
    args = ["fit", str(path), "--radius", "0.005", "--rpm", "33.3"]
    figure = tmp_path / "fit.png"
    without, proc = _blocked(args, [*args, "--plot", str(figure)])
    assert without.returncode == 0, without.stderr
    assert json.loads(without.stdout)["selected"] in fit.MODELS
    assert proc.returncode == 2
    assert proc.stdout == ""
    assert proc.stderr.count("\n") == 1
    assert "--plot needs matplotlib" in proc.stderr
    assert not figure.exists()


# --------------------------------------------------------------------------- bad input
GOOD = "t,x,y\n0.0,0.05,0.0\n0.1,0.049,0.005\n0.2,0.047,0.01\n0.3,0.044,0.015\n0.4,0.04,0.02\n"

BAD_FILES = {
    "missing column": ("t,x,z\n0,1,2\n", [":1:", "column 'y'"]),
    "non-numeric value": (
        "# comment\nt,x,y\n0,0.05,0\n0.1,abc,0.01\n",
        [":4:", "column 'x'", "field 2", "'abc'"],
    ),
    "empty value": ("t,x,y\n0,0.05,0\n0.1,0.05,\n", [":3:", "column 'y'", "field 3"]),
    "nan": ("t,x,y\n0,0.05,0\n0.1,nan,0\n", [":3:", "column 'x'", "not a finite number"]),
    "infinity": ("t,x,y\n0,0.05,0\n0.1,0.05,-inf\n", [":3:", "column 'y'", "not a finite"]),
    "time goes back": (
        "t,x,y\n0,0.05,0\n0.2,0.05,0\n0.1,0.05,0\n",
        [":4:", "column 't'", "does not increase"],
    ),
    "time repeated": ("t,x,y\n0,0.05,0\n0,0.05,0\n", [":3:", "column 't'", "does not increase"]),
    "fewer points than parameters": (
        "t,x,y\n0,0.05,0\n0.1,0.05,0\n0.2,0.05,0\n",
        [":4:", "3 frames", "at least 4", "7 parameters"],
    ),
    "no frames": ("# nothing\nt,x,y\n", [":2:", "0 frames"]),
    "short row": ("t,x,y\n0,0.05,0\n0.1,0.05\n", [":3:", "2 fields", "header on line 1 has 3"]),
    "column twice": ("t,x,y,x\n", [":1:", "column 'x' appears twice"]),
    "empty file": ("", [":1:", "no header"]),
    "not text": (b"t,x,y\n0,\xff\xfe,0\n", [":2:", "not UTF-8"]),
}


def _check_bad(proc: subprocess.CompletedProcess, expected: list[str]) -> None:
    assert proc.returncode == 2, proc.stderr
    assert proc.stdout == ""
    assert proc.stderr.endswith("\n")
    assert proc.stderr.count("\n") == 1, proc.stderr  # one line, no traceback
    assert "Traceback" not in proc.stderr
    for text in expected:
        assert text in proc.stderr, (text, proc.stderr)


@pytest.mark.parametrize("case", list(BAD_FILES))
def test_bad_file(tmp_path: Path, capsys: pytest.CaptureFixture[str], case: str) -> None:
    content, expected = BAD_FILES[case]
    path = tmp_path / "film.csv"
    if isinstance(content, bytes):
        path.write_bytes(content)
    else:
        path.write_text(content)
    proc = run_here(capsys, str(path), "--radius", "0.005", "--rpm", "33.3")
    _check_bad(proc, [f"{path}:", *expected])


@pytest.mark.parametrize("kind", ["missing", "directory"])
def test_unreadable_file(tmp_path: Path, capsys: pytest.CaptureFixture[str], kind: str) -> None:
    path = tmp_path / ("nowhere.csv" if kind == "missing" else "folder")
    if kind == "directory":
        path.mkdir()
    proc = run_here(capsys, str(path), "--radius", "0.005", "--rpm", "33.3")
    _check_bad(proc, [str(path), "cannot read the file"])


def test_bad_input_end_to_end(tmp_path: Path) -> None:
    """The console script itself: one line on stderr, exit status 2, no traceback."""
    content, expected = BAD_FILES["non-numeric value"]
    path = tmp_path / "film.csv"
    path.write_text(content)
    _check_bad(run(str(path), "--radius", "0.005", "--rpm", "33.3"), [f"{path}:", *expected])


def test_bad_option_is_reported_before_the_file_is_read(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "film.csv"
    path.write_text(BAD_FILES["fewer points than parameters"][0])
    _check_bad(run_here(capsys, str(path), "--radius", "0.005", "--rpm", "-1"), ["--rpm", "> 0"])


BAD_OPTIONS = {
    "negative radius": (["--radius", "-0.005", "--rpm", "33"], ["--radius", "> 0", "-0.005"]),
    "zero radius": (["--radius", "0", "--rpm", "33"], ["--radius", "> 0"]),
    "negative omega": (["--radius", "0.005", "--omega", "-3.5"], ["--omega", "> 0", "-3.5"]),
    "infinite omega": (["--radius", "0.005", "--omega", "inf"], ["--omega", "finite"]),
    "negative rpm": (["--radius", "0.005", "--rpm", "-33"], ["--rpm", "> 0"]),
    "nan k": (["--radius", "0.005", "--rpm", "33", "--k", "nan"], ["--k", "finite"]),
    "negative mass": (["--radius", "0.005", "--rpm", "33", "--mass", "-1"], ["--mass", "> 0"]),
    "infinite axis": (["--radius", "0.005", "--rpm", "33", "--axis", "0", "inf"], ["--axis"]),
    "not a number": (["--radius", "five", "--rpm", "33"], ["--radius", "'five'"]),
    "no rate": (["--radius", "0.005"], ["--omega", "--rpm", "required"]),
    "two rates": (["--radius", "0.005", "--rpm", "33", "--omega", "3"], ["not allowed"]),
    "plot format": (["--radius", "0.005", "--rpm", "33", "--plot", "fit.xyz"], ["'xyz'"]),
    "plot folder": (
        ["--radius", "0.005", "--rpm", "33", "--plot", "/nonexistent/fit.png"],
        ["--plot", "/nonexistent"],
    ),
}


@pytest.mark.parametrize("case", list(BAD_OPTIONS))
def test_bad_option(tmp_path: Path, capsys: pytest.CaptureFixture[str], case: str) -> None:
    args, expected = BAD_OPTIONS[case]
    path = tmp_path / "film.csv"
    path.write_text(GOOD)
    proc = run_here(capsys, str(path), *args)
    _check_bad(proc, expected)


def test_good_file_passes_the_checks(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """The file the bad cases are variations of is accepted (five frames), fitted, and too
    short for a selection: none is made, and a warning line says why (exit status 0)."""
    path = tmp_path / "film.csv"
    path.write_text(GOOD)
    proc = run_here(capsys, str(path), "--radius", "0.005", "--rpm", "33.3")
    assert proc.returncode == 0, proc.stderr
    out = json.loads(proc.stdout)
    assert out["data"]["n_frames"] == 5
    assert math.isfinite(out["slipping"]["aic"])
    assert out["selected"] is None
    assert out["selection"]["decisive"] is False
    assert "no model selected: 5 frames" in out["selection"]["reason"]
    lines = proc.stderr.splitlines()
    assert all(line.startswith("turntable fit: warning: ") for line in lines), lines
    assert any("no model selected" in line for line in lines)


SPREADSHEET_VARIANTS = {
    "quoted header": '"t","x","y"\n' + GOOD.split("\n", 1)[1],
    "quoted values": GOOD.replace("0.05,", '"0.05",'),
    "tab-separated": GOOD.replace(",", "\t"),
    "semicolon-separated, extra column": "\n".join(
        line.replace(",", ";") + (";id" if i == 0 else f";frame {i}")
        for i, line in enumerate(GOOD.splitlines())
    ),
}


@pytest.mark.parametrize("case", list(SPREADSHEET_VARIANTS))
def test_spreadsheet_variants_read_the_same_film(tmp_path: Path, case: str) -> None:
    """Quoted fields and tab- or semicolon-separated files, as spreadsheets export them,
    give the same frames as the plain comma-separated file."""
    plain, variant = tmp_path / "plain.csv", tmp_path / "variant.csv"
    plain.write_text(GOOD)
    variant.write_text(SPREADSHEET_VARIANTS[case])
    want, got = film.read_film(plain), film.read_film(variant)
    for column in film.COLUMNS:
        np.testing.assert_array_equal(getattr(got, column), getattr(want, column))


def test_a_delimiter_other_than_the_headers_is_refused(tmp_path: Path) -> None:
    """The header fixes the delimiter: a frame written with another one is a row with the
    wrong number of fields, named by its line."""
    path = tmp_path / "mixed.csv"
    path.write_text("t\tx\ty\n0\t0.05\t0\n0.1,0.05,0.01\n")
    with pytest.raises(film.FilmError, match=r"mixed.csv:3: 1 fields, but the header"):
        film.read_film(path)


def _still_film(tmp_path: Path, x: float, y: float, fps: float = 60.0) -> Path:
    """A noiseless film of a ball that stays at (x, y) m for 5 s at ``fps`` frames/s."""
    path = tmp_path / "still.csv"
    rows = "".join(f"{i / fps!r},{x!r},{y!r}\n" for i in range(round(5 * fps)))
    path.write_text("t,x,y\n" + rows)
    return path


@pytest.mark.parametrize("fps", [50.0, 60.0])
def test_a_noiseless_film_of_a_ball_at_rest(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], fps: float
) -> None:
    """A ball at rest 5 cm from the axis, without noise, is an equilibrium of the slipping
    model for every mu0 (2.3): the command gives no confident value of mu0 (no one-sided
    limit drawn from rounding errors), and the exact fit's residuals are not taken for a
    misfit. Two frame rates, which end the search at a bound and inside the range."""
    path = _still_film(tmp_path, 0.05, 0.0, fps)
    proc = run_here(capsys, str(path), "--radius", "0.005", "--rpm", "33.3")
    lines = _warnings(proc)
    out = json.loads(proc.stdout)
    entry = out["slipping"]
    # never a confident value: either the search ended at a bound, with the whole range as
    # its limit, or inside it, with no finite standard error or one flagged as meaningless
    if entry["mu0"] is None:
        assert entry["mu0_upper_limit"] == pytest.approx(fit.BOUNDS["slipping"][1])
        assert any("slipping: mu0" in line and "anywhere" in line for line in lines), lines
    elif entry["mu0_stderr"] is None:
        assert any("slipping: the film does not constrain mu0" in line for line in lines)
    else:
        assert entry["mu0_relative_stderr"] > fit.LINEAR_RELATIVE_ERROR
        assert any("slipping: the relative standard error of mu0" in line for line in lines)
    assert out["slipping"]["residuals_white"] is True
    assert not any("neither model fits" in line for line in lines), lines


def test_no_selection_between_two_exact_fits(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A ball at rest on the axis is an equilibrium of both models: both fit the noiseless
    film to rounding, and AICc, which compares logarithms of residual sums, is not asked to
    weigh rounding errors: no model is selected, and the reason says why."""
    path = _still_film(tmp_path, 0.02, -0.01)
    proc = run_here(
        capsys, str(path), "--radius", "0.005", "--rpm", "33.3", "--axis", "0.02", "-0.01"
    )
    _warnings(proc)
    out = json.loads(proc.stdout)
    assert out["selected"] is None
    assert "reproduce the positions to rounding" in out["selection"]["reason"]


def _worked_example() -> tuple[list[str], str]:
    """The command and the JSON excerpt of the worked example of docs/fitting.md ("A
    worked example")."""
    page = (ROOT / "docs" / "fitting.md").read_text(encoding="utf-8")
    section = page.split("## A worked example", 1)[1].split("\n## ", 1)[0]
    shell = section.split("```sh\n", 1)[1].split("```", 1)[0].replace("\\\n", " ")
    (command,) = [line for line in shell.splitlines() if line.startswith(".venv/bin/turntable ")]
    excerpt = section.split("```text", 1)[1].split("```", 1)[0]
    return command.split()[2:], excerpt


def test_the_worked_example_is_what_the_command_prints(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The worked example of docs/fitting.md, run on the synthetic film that the
    configuration in the repository makes (as rule synthetic_film writes it): every number
    of its JSON excerpt is the command's, to the digits shown, and so are the model
    selected and the flags."""
    import re

    config = full_config()
    args, excerpt = _worked_example()
    name = Path(args[0]).stem
    (spec,) = [f for f in config["synthetic_film"]["films"] if f["name"] == name]
    rig = film.rig_from_config(config["film"])
    data = fit.simulate_film(
        spec["model"], spec["coefficient"], rig.state0, rig.setup, rig.camera, spec["seed"]
    )
    path = tmp_path / f"{name}.csv"
    film.write_film(path, data, ["SYNTHETIC DATA"])
    args[0] = str(path)
    if "--plot" in args:
        args[args.index("--plot") + 1] = str(tmp_path / "fit.png")
    proc = run_here(capsys, *args)
    assert proc.returncode == 0, proc.stderr
    out = json.loads(proc.stdout)
    assert (tmp_path / "fit.png").exists() == ("--plot" in args)
    # the selection, the flags and the warnings as shown
    assert f'"selected": "{out["selected"]}"' in excerpt
    for key in ("decisive", "residuals_white", "synthetic"):
        shown = re.findall(rf'"{key}": (true|false)', excerpt)
        assert shown, key
    assert f'"decisive": {str(out["selection"]["decisive"]).lower()}' in excerpt
    assert f'"synthetic": {str(out["data"]["synthetic"]).lower()}' in excerpt
    assert ('"warnings": []' in excerpt) == (out["warnings"] == [])
    # every number shown, in the entry it is shown in, to its digits
    entries = {"selection": out["selection"], "data": out["data"], "consistency": None}
    entries |= {m: out[m] for m in fit.MODELS}
    entries["consistency"] = out["consistency"]
    checked = 0
    for block in re.split(r"\n \"", excerpt):
        entry_name = block.split('"', 1)[0]
        entry = entries.get(entry_name)
        if entry is None:
            continue
        # one level of nesting (the Akaike weights), by the inner keys
        entry = entry | {k: v for d in entry.values() if isinstance(d, dict) for k, v in d.items()}
        for key, text in re.findall(r'"(\w+)": (-?\d[\d.e+-]*)', block):
            value = entry[key]
            digits = len(text.split("e")[0].split(".")[1]) if "." in text else 0
            tolerance = (
                0.5 * 10.0 ** (-digits) * (10.0 ** int(text.split("e")[1]) if "e" in text else 1)
            )
            assert abs(value - float(text)) <= tolerance * (1 + 1e-9), (
                entry_name,
                key,
                value,
                text,
            )
            checked += 1
    assert checked >= 12, checked


def test_rig_of_the_configuration() -> None:
    """Section film: a 1 cm steel ball (7850 kg/m^3) at 33 1/3 rpm, put down at rest 5 cm
    from the axis, filmed at 240 frames/s for 10 s with 0.2 mm noise."""

    section = full_config()["film"]
    rig = film.rig_from_config(section)
    assert 2 * rig.setup.radius == pytest.approx(0.01)
    assert rig.mass == pytest.approx(7850 * 4 / 3 * math.pi * rig.setup.radius**3, rel=1e-3)
    assert rig.setup.omega == pytest.approx(2 * math.pi * (100 / 3) / 60)
    assert (rig.camera.fps, rig.camera.noise, rig.camera.duration) == (240.0, 2e-4, 10.0)
    assert list(rig.state0) == [10.0, 0.0, 0.0, 0.0, 0.0, 0.0]


# --------------------------------------------------------------------------- warnings
RIG = film.Setup(0.005, film.rpm_to_omega(100.0 / 3.0), 0.4)


def _rig_file(
    tmp_path: Path,
    model: str,
    coefficient: float,
    camera: film.Camera,
    seed: int,
    true: film.Setup = RIG,
    flip: bool = False,
    header: bool = False,
) -> Path:
    """A film of the configured ball (put down at rest 5 cm from the axis) made with the
    Omega and axis of ``true``; y negated if ``flip``; with the SYNTHETIC header if
    ``header``."""
    z0 = film.state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], true)
    if model == "rolling_resistance":
        z0 = tt.no_slip_state(z0, true.k)
    data = fit.simulate_film(model, coefficient, z0, true, camera, seed)
    if flip:
        data = film.Film(data.t, data.x, -data.y)
    path = tmp_path / f"{model}-{seed}.csv"
    comments = fit.synthetic_header(model, coefficient, z0, true, camera, seed) if header else []
    film.write_film(path, data, comments)
    return path


def _warnings(proc: subprocess.CompletedProcess) -> list[str]:
    """The warning lines of a completed fit (exit 0, every stderr line a warning)."""
    assert proc.returncode == 0, proc.stderr
    lines = proc.stderr.splitlines()
    assert all(line.startswith("turntable fit: warning: ") for line in lines), lines
    assert "Traceback" not in proc.stderr
    assert json.loads(proc.stdout)["warnings"] == [
        line.removeprefix("turntable fit: warning: ") for line in lines
    ]
    return lines


def test_wrong_rate_warns_and_fit_omega_recovers(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A slipping film of a turntable 0.4 % faster than --omega: with the given rate the
    rolling model is selected, by a large AICc difference but not decisively (the fit with
    Omega free contradicts the given rate), and a warning says that with Omega free the
    slipping model is selected;
    with --fit-omega the slipping model is selected, mu0 and Omega lie within 3 standard
    errors of the truth, and nothing is reported."""
    true = RIG._replace(omega=RIG.omega * 1.004)
    path = _rig_file(tmp_path, "slipping", 3.0, film.Camera(60.0, 2e-4, 6.0), 3, true)
    args = [str(path), "--radius", "0.005", "--omega", repr(RIG.omega)]
    lines = _warnings(run_here(capsys, *args))
    wrong = json.loads(run_here(capsys, *args).stdout)
    assert wrong["selected"] == "rolling_resistance"
    assert wrong["selection"]["aicc_difference"] > fit.DECISIVE
    assert wrong["selection"]["decisive"] is False
    assert "rests on the given Omega" in wrong["selection"]["reason"]
    assert any("selects slipping" in line and "--fit-omega" in line for line in lines), lines
    proc = run_here(capsys, *args, "--fit-omega")
    assert _warnings(proc) == []
    out = json.loads(proc.stdout)
    assert out["setup"]["fit_omega"] is True
    assert out["consistency"]["freed"] == ["axis"]
    assert out["selected"] == "slipping"
    entry = out["slipping"]
    assert abs(entry["mu0"] - 3.0) < 3 * entry["mu0_stderr"]
    assert abs(entry["omega_rad_s"] - true.omega) < 3 * entry["omega_stderr_rad_s"]
    assert out["slipping"]["n_parameters"] == 8


def test_clockwise_film_warns(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A film of a clockwise turntable whose y was not negated: neither model fits (rms
    residual far above the 0.2 mm noise), and the warning names the sign of y."""
    path = _rig_file(tmp_path, "slipping", 3.0, film.Camera(60.0, 2e-4, 6.0), 0, flip=True)
    proc = run_here(capsys, str(path), "--radius", "0.005", "--omega", repr(RIG.omega))
    lines = _warnings(proc)
    assert any("neither model fits" in line and "sign of y" in line for line in lines), lines
    out = json.loads(proc.stdout)
    assert out[out["selected"]]["rms_residual_m"] > 10 * 2e-4
    assert out[out["selected"]]["residuals_white"] is False


def test_coefficient_at_the_bound_is_a_limit(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """mu0 = 3000 filmed at 30 frames/s for 6 s: the slipping fit runs into the end of the
    search range; the JSON gives no value but a lower limit, below the truth, and a warning
    line says so; exit status 0."""
    path = _rig_file(tmp_path, "slipping", 3000.0, film.Camera(30.0, 3e-4, 6.0), 1)
    proc = run_here(capsys, str(path), "--radius", "0.005", "--omega", repr(RIG.omega))
    lines = _warnings(proc)
    assert any("mu0 ran into the upper end" in line for line in lines), lines
    entry = json.loads(proc.stdout)["slipping"]
    assert entry["mu0"] is None
    assert entry["at_bound"] is True
    assert entry["mu0_lower_limit"] < 3000.0
    assert entry["mu0_search_bound"] == pytest.approx(fit.BOUNDS["slipping"][1])


def test_time_in_milliseconds_warns(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Times written in ms: the warning asks whether t is in seconds."""
    data = film.read_film(_rig_file(tmp_path, "slipping", 3.0, film.Camera(60.0, 2e-4, 1.0), 0))
    path = tmp_path / "ms.csv"
    film.write_film(path, film.Film(1000.0 * data.t, data.x, data.y))
    lines = _warnings(run_here(capsys, str(path), "--radius", "0.005", "--rpm", "33.3"))
    assert any("between frames" in line and "t is in seconds" in line for line in lines), lines


def test_weak_selection_is_not_decisive(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """15 frames at 240 frames/s, where the two motions differ by less than the noise: a
    model is selected, "decisive": false, and a warning line gives the AICc difference."""
    path = _rig_file(tmp_path, "slipping", 3.0, film.Camera(240.0, 2e-4, 14 / 240), 0)
    proc = run_here(capsys, str(path), "--radius", "0.005", "--omega", repr(RIG.omega))
    lines = _warnings(proc)
    sel = json.loads(proc.stdout)["selection"]
    assert sel["decisive"] is False
    assert sel["aicc_difference"] < 10
    assert any("is not decisive: AICc difference" in line for line in lines), lines


def test_synthetic_films_are_marked_in_the_json(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    camera = film.Camera(30.0, 3e-4, 4.0)
    marked = _rig_file(tmp_path, "slipping", 3.0, camera, 0, header=True)
    assert marked.read_text().startswith("# SYNTHETIC")
    proc = run_here(capsys, str(marked), "--radius", "0.005", "--omega", repr(RIG.omega))
    out = json.loads(proc.stdout)
    assert out["data"]["synthetic"] is True
    assert "turns" not in out["data"]
    assert out["data"]["turntable_turns"] == pytest.approx(RIG.omega * 4.0 / (2 * math.pi))


# --------------------------------------------------------------------------- robustness
EXTREME = {
    "positions of 1e300 m": ("x", lambda d: (d.t, 1e300 * d.x / 0.05, d.y), []),
    "positions of 1e-300 m": ("", lambda d: (d.t, 1e-300 * d.x, 1e-300 * d.y), []),
    "times of 1e300 s": ("t", lambda d: (1e300 * (d.t + 1.0), d.x, d.y), []),
    "times of 1e-200 s": ("", lambda d: (1e-200 * d.t, d.x, d.y), []),
    "radius of 1e-300 m": ("x", lambda d: (d.t, d.x, d.y), ["--radius", "1e-300"]),
    "rate of 1e300 rad/s": ("t", lambda d: (d.t, d.x, d.y), ["--omega", "1e300"]),
}


@pytest.mark.parametrize("case", list(EXTREME))
def test_extreme_numbers(tmp_path: Path, capsys: pytest.CaptureFixture[str], case: str) -> None:
    """Numbers far outside any experiment: either one error line naming the file, line and
    column (exit 2; values beyond 1e100 radii, or times beyond 1e100 / Omega) or a fit with
    warning lines only (exit 0), never a traceback or numpy's RuntimeWarning; with --plot
    too (the JSON is written first)."""
    column, change, options = EXTREME[case]
    data = film.read_film(_rig_file(tmp_path, "slipping", 3.0, film.Camera(30.0, 3e-4, 2.0), 0))
    path = tmp_path / "extreme.csv"
    film.write_film(path, film.Film(*change(data)), digits=17)
    given = {"--radius": "0.005", "--omega": repr(RIG.omega)}
    given.update(zip(options[::2], options[1::2], strict=True))
    args = [word for pair in given.items() for word in pair]
    figure = tmp_path / "fit.png"
    proc = run_here(capsys, str(path), *args, "--plot", str(figure))
    assert "Traceback" not in proc.stderr
    assert "Warning" not in proc.stderr  # RuntimeWarning, UserWarning
    if column:
        _check_bad(proc, [f"{path}:", f"column '{column}'", "too large for the fit"])
    else:
        assert proc.returncode in (0, 1), proc.stderr
        assert all(line.startswith("turntable fit: ") for line in proc.stderr.splitlines())
        json.loads(proc.stdout)


def test_plot_that_cannot_be_drawn(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """If drawing fails, the JSON is already on stdout; one line on stderr, exit status 1."""

    def broken(*_: object) -> None:
        raise TypeError("unsupported format string passed to NoneType.__format__")

    monkeypatch.setattr(fitplot, "plot_fit", broken)
    path = _rig_file(tmp_path, "slipping", 3.0, film.Camera(30.0, 3e-4, 4.0), 0)
    figure = tmp_path / "fit.png"
    proc = run_here(capsys, str(path), "--radius", "0.005", "--rpm", "33.3", "--plot", str(figure))
    assert proc.returncode == 1
    assert json.loads(proc.stdout)["selected"] in fit.MODELS
    errors = [line for line in proc.stderr.splitlines() if "error" in line]
    assert errors == [f"turntable fit: error: --plot {figure}: unsupported format string "
                      "passed to NoneType.__format__"]  # fmt: skip
    assert "Traceback" not in proc.stderr


def test_plot_draws_missing_values_and_limits(tmp_path: Path) -> None:
    """The drawing of a JSON with None values (no finite rolling fit, no AICc difference)
    and a coefficient reported as a limit: drawn, with the limit in the label."""

    camera = film.Camera(30.0, 3e-4, 6.0)
    data = film.read_film(_rig_file(tmp_path, "slipping", 3000.0, camera, 1))
    out = finite_or_none(fit.result_json(fit.fit_film(data, RIG), RIG, data))
    assert out["slipping"]["mu0"] is None
    out["rolling_resistance"] = {
        key: value for key, value in out["rolling_resistance"].items() if "limit" not in key
    }
    out["rolling_resistance"]["state0"] = [None] * 6
    out["rolling_resistance"]["delta"] = None
    out["rolling_resistance"]["rms_residual_m"] = None
    out["selection"]["aicc_difference"] = None
    figure = tmp_path / "fit.png"
    fitplot.plot_fit(figure, data, out)
    assert figure.read_bytes().startswith(b"\x89PNG")
    assert fitplot.coefficient_text(out["slipping"], "mu0").startswith("> ")
    assert fitplot.coefficient_text(out["rolling_resistance"], "delta") == "n/a"


def test_closed_stdout_ends_quietly(tmp_path: Path) -> None:
    """`turntable fit ... | head -c 10`: when the reader is gone before the JSON is written,
    the command ends without a traceback (status 1, as Python advises for SIGPIPE)."""
    path = _rig_file(tmp_path, "slipping", 3.0, film.Camera(30.0, 3e-4, 4.0), 0)
    proc = subprocess.Popen(
        [COMMAND, "fit", str(path), "--radius", "0.005", "--rpm", "33.3"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    proc.stdout.close()  # the reader leaves before the fit is done
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 1
    assert b"Traceback" not in err
    assert b"BrokenPipe" not in err
