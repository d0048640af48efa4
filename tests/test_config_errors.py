"""Configuration mistakes: each is refused before any job runs, in a few lines naming the
file, the line, the key and what is expected; the outputs of the last good build keep
their bytes.

The checks live in workflow/config_checks.py and are driven by the schema
workflow/schemas/config.schema.yaml. Most cases call them directly on a configuration
file written to a temporary directory (fast); the cases of issue 9 also run Snakemake
end to end on a copy of the shared clean build of tests/test_pipeline.py.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import yaml

import test_pipeline as pipeline
import turntable
from shared_build import build_once, shared_dir
from test_pipeline import sha256
from turntable import fit, rolling

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "workflow"))
import config_checks  # noqa: E402

CONFIG_TEXT = (ROOT / "config" / "config.yaml").read_text()
SCHEMA, _ = config_checks.load_schema()
CLAIMS_SCHEMA = yaml.safe_load((ROOT / "src/turntable/claims/params.schema.yaml").read_text())

#: Lines of the whole output of a refused `snakemake` run: Snakemake's own three (profile,
#: "WorkflowError in file Snakefile", the Snakefile line), the header and the problem.
MAX_OUTPUT_LINES = 6


# --------------------------------------------------------------------------- helpers
def message(tmp_path: Path, text: str, name: str = "config.yaml") -> str | None:
    """What the workflow says about the configuration file ``text`` (None: accepted)."""
    path = tmp_path / name
    path.write_text(text)
    problem = config_checks.file_problem(path)
    if problem:
        return problem
    config = yaml.load(text, Loader=yaml.FullLoader)  # as Snakemake reads it
    return config_checks.config_problem(config, [path])


def replaced(old: str, new: str, text: str = CONFIG_TEXT) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


def line_of(text: str, fragment: str) -> int:
    """1-based number of the line of ``text`` that contains ``fragment`` (only one does)."""
    found = [i + 1 for i, line in enumerate(text.splitlines()) if fragment in line]
    assert len(found) == 1, (fragment, found)
    return found[0]


def dumped(config: dict[str, Any]) -> str:
    return yaml.safe_dump(config, sort_keys=False)


# --------------------------------------------------------------------------- accepted
def test_the_project_configuration_is_accepted(tmp_path: Path) -> None:
    assert message(tmp_path, CONFIG_TEXT) is None
    assert message(tmp_path, dumped(pipeline.base_config())) is None


# --------------------------------------------------------------------------- refused
# (edit of config/config.yaml, fragment of the line it is about, texts the message holds)
CASES: dict[str, tuple[Callable[[str], str], str, list[str]]] = {
    "float for an integer (issue 9)": (
        lambda t: replaced("  n_points: 400\n\nfig3", "  n_points: 400.0\n\nfig3", t),
        "n_points: 400.0",
        ["fig2_spectrum.n_points = 400.0 is not an integer", "write 400", "from 2 to 100000"],
    ),
    "1e-4 read as text (issue 9)": (
        lambda t: replaced("mu0_range: [1.0e-4, 1.0e+3]", "mu0_range: [1e-4, 1.0e+3]", t),
        "mu0_range: [1e-4",
        ["fig2_spectrum.mu0_range[0] = '1e-4' is text", "write 1.0e-4"],
    ),
    "quoted integer": (
        lambda t: replaced("n_points: 300", 'n_points: "300"', t),
        'n_points: "300"',
        ["fig5_damping_ratio.n_points = '300' is text", "write 300 without quotes"],
    ),
    "misspelt section (issue 9)": (
        lambda t: replaced("fig2_spectrum:", "fig2_spectrm:", t),
        "fig2_spectrm:",
        ["unknown section 'fig2_spectrm'", "did you mean 'fig2_spectrum'"],
    ),
    "unknown key": (
        lambda t: replaced("  tilt: 0.35", "  tilt: 0.35\n  colour: red", t),
        "colour: red",
        ["unknown key 'colour' in fig1_schematic", "known: tilt"],
    ),
    "misspelt key": (
        lambda t: replaced("  n_frames: 160", "  n_frame: 160", t),
        "n_frame: 160",
        ["unknown key 'n_frame' in animation", "did you mean 'n_frames' (missing)?"],
    ),
    "missing key": (
        lambda t: replaced("  mu0_layer: [10.0, 100.0, 1000.0]\n", "", t),
        "fig6_limit:",
        ["missing key 'mu0_layer' in fig6_limit", "default: [10.0, 100.0, 1000.0]"],
    ),
    "missing section": (
        lambda t: t[: t.index("# Animation")],
        "",
        ["missing section 'animation'"],
    ),
    "two films of one name": (
        lambda t: replaced("{name: rolling, model", "{name: slipping, model", t),
        "{name: slipping, model: rolling",
        ["synthetic_film.films[1].name = 'slipping' is the name of an earlier entry"],
    ),
    "film of an unknown model": (
        lambda t: replaced("model: rolling_resistance, coeff", "model: rolling, coeff", t),
        "model: rolling, coeff",
        ["synthetic_film.films[1].model = 'rolling'", "rolling_resistance"],
    ),
    "zero friction": (
        lambda t: replaced("mu0: [0.1, 1.0]", "mu0: [0.1, 0.0]", t),
        "mu0: [0.1, 0.0]",
        ["fig3_modal_terms.mu0[1] = 0.0", "from 1e-12 to 1e+12"],
    ),
    "negative inertia ratio": (
        lambda t: replaced("  k: 0.4\n  mu0_range: [1.0e-4", "  k: -0.4\n  mu0_range: [1.0e-4", t),
        "k: -0.4",
        ["fig2_spectrum.k = -0.4", "from 1e-06 to 1"],
    ),
    "not a number": (
        lambda t: replaced("  dpi: 200", "  dpi: .nan", t),
        "dpi: .nan",
        ["style.dpi = NaN is not a finite number"],
    ),
    "boolean": (
        lambda t: replaced("  tilt: 0.35", "  tilt: yes", t),
        "tilt: yes",
        ["fig1_schematic.tilt = true is a boolean"],
    ),
    "empty value": (
        lambda t: replaced("  wz: 0.5", "  wz:", t),
        "wz:",
        ["animation.wz is empty", "from -100 to 100"],
    ),
    "empty list": (
        lambda t: replaced("mu0_trajectories: [1.0, 3.0, 10.0, 100.0]", "mu0_trajectories: []", t),
        "mu0_trajectories: []",
        ["fig6_limit.mu0_trajectories = [] has 0 items", "1 to 10 items"],
    ),
    "section that is not a section": (
        lambda t: replaced("style:\n  dpi: 200", "style: 200", t),
        "style: 200",
        ["style = 200 is a number; expected a section"],
    ),
    "key given twice": (
        lambda t: replaced("  frame_ms: 60", "  frame_ms: 60\n  frame_ms: 40", t),
        "frame_ms: 40",
        ["animation.frame_ms is given twice"],
    ),
    "reversed time span": (
        lambda t: replaced("t_span: [0.0, 8.0]", "t_span: [8.0, 0.0]", t),
        "t_span: [8.0, 0.0]",
        ["fig3_modal_terms.t_span = [8.0, 0.0]", "start < end"],
    ),
    "one of several spans reversed": (
        lambda t: replaced("[0.0, 70.0], [0.0, 150.0]]", "[70.0, 0.0], [0.0, 150.0]]", t),
        "[70.0, 0.0]",
        ["fig4_trajectories.t_span[3] = [70.0, 0.0]"],
    ),
    "reversed mu0 range": (
        lambda t: replaced("mu0_range: [1.0e-6, 1.0e+2]", "mu0_range: [1.0e+2, 1.0e-6]", t),
        "mu0_range: [1.0e+2, 1.0e-6]",
        ["fig5_damping_ratio.mu0_range = [100.0, 1e-06]", "start < end"],
    ),
    "fewer spans than mu0": (
        lambda t: replaced("[[0.0, 45.0], [0.0, 35.0], ", "[", t),
        "t_span: [[0.0, 45.0], [0.0, 70.0]",
        ["fig4_trajectories.t_span has 3 spans but fig4_trajectories.mu0 has 5 values"],
    ),
    "time beyond the overflow of a double (issue 9)": (
        lambda t: replaced("[[0.0, 45.0],", "[[0.0, 1.0e+5],", t),
        "[[0.0, 1.0e+5]",
        ["fig4_trajectories.t_span[0] ends at t = 100000", "mu0 = 0.02", "turntable.max_time"],
    ),
    "study time beyond the overflow": (
        lambda t: replaced("t_span: [0.0, 20.0]", "t_span: [0.0, 1.0e+5]", t),
        "t_span: [0.0, 1.0e+5]",
        ["study.t_span ends at t = 100000", "turntable.max_time"],
    ),
    "initial-layer time beyond the overflow": (
        lambda t: replaced(
            "mu0_layer: [10.0, 100.0, 1000.0]\n  layer_t_span: [1.0e-4, 30.0]",
            "mu0_layer: [0.1]\n  layer_t_span: [1.0e-4, 1.0e+5]",
            t,
        ),
        "layer_t_span: [1.0e-4, 1.0e+5]",
        ["fig6_limit.layer_t_span ends at t = 100000", "fig6_limit.layer_state"],
    ),
    "rolling ball beyond the overflow": (
        lambda t: replaced(
            "comparison: equal_power\n  t_span: [0.0, 70.0]",
            "comparison: equal_coefficient\n  t_span: [0.0, 5.0e+3]",
            t,
        ),
        "t_span: [0.0, 5.0e+3]",
        ["fig7_rolling_resistance.t_span ends at t = 5000, too late for the rolling ball"],
    ),
    "film too short for the fits (3 frames)": (
        lambda t: replaced("  duration_s: 10.0", "  duration_s: 0.01", t),
        "duration_s: 0.01",
        [
            "film.duration_s = 0.01 s at film.fps = 240 frames/s gives 3 frames",
            "expected at least 16 frames: duration_s >= 0.0625",
        ],
    ),
    "film of too many frames": (
        lambda t: replaced("  fps: 240.0", "  fps: 1.0e+6", t),
        "duration_s: 10.0",
        ["gives 10000001 frames", "expected at most 1000000 frames"],
    ),
    "film beyond the overflow of a double": (
        lambda t: replaced("  rpm: 33.333333333333336", "  rpm: 10000.0", t),
        "duration_s: 10.0",
        [
            "film.duration_s = 10 s at film.rpm = 10000 ends at t Omega = 10472",
            "slipping ball of Fig. 8 (mu0 = 0.0793254)",
            "turntable.max_time); expected duration_s <= 7.86616",
        ],
    ),
    "ball of the animation out of its panels": (
        lambda t: replaced("  t_end: 40.0", "  t_end: 1000.0", t),
        "t_end: 1000.0",
        ["animation.t_end = 1000: by then the ball goes 1.905e+10 R", "pixels wide", "158.5 R"],
    ),
    "unknown comparison": (
        lambda t: replaced("comparison: equal_power", "comparison: equal-power", t),
        "comparison: equal-power",
        ["'equal-power'", "one of equal_coefficient, equal_power, equal_decay"],
    ),
    "repeated study k": (
        lambda t: replaced(
            "study:\n  k: [0.05, 0.4, 0.6666666666666666, 1.0]", "study:\n  k: [0.4, 0.4]", t
        ),
        "k: [0.4, 0.4]",
        ["study.k = [0.4, 0.4] repeats a value"],
    ),
    "plain http address": (
        lambda t: replaced("repository: https://", "repository: http://", t),
        "repository: http://",
        ["paper.repository = 'http://", "a text matching ^https://"],
    ),
    "timestamp as a date": (
        lambda t: replaced("timestamp: 1735689600", "timestamp: 2025-01-01", t),
        "timestamp: 2025-01-01",
        ["paper.timestamp", "an integer from 0 to 253402300799"],
    ),
    "unknown claims parameter": (
        lambda t: replaced("claims: {}", "claims: {n_pointz: 481}", t),
        "claims: {n_pointz",
        ["unknown key 'n_pointz' in claims; did you mean 'n_points'?"],
    ),
    "float for a claims count": (
        lambda t: replaced("claims: {}", "claims:\n  n_states: 4.0", t),
        "n_states: 4.0",
        ["claims.n_states = 4.0 is not an integer", "write 4"],
    ),
    "all-zero state of the scaling claim": (
        lambda t: replaced("claims: {}", "claims:\n  state_si: [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]", t),
        "state_si:",
        ["claims.state_si = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0] is not allowed", "not all zero"],
    ),
}


@pytest.mark.parametrize("case", list(CASES))
def test_a_mistake_is_told_in_one_line_with_file_line_key_and_expectation(
    tmp_path: Path, case: str
) -> None:
    edit, fragment, expected = CASES[case]
    text = edit(CONFIG_TEXT)
    got = message(tmp_path, text)
    assert got is not None, "accepted"
    header, *problems = got.splitlines()
    assert header == config_checks.HEADER
    assert len(problems) == 1, got
    where = f"config.yaml:{line_of(text, fragment)}: " if fragment else "config.yaml: "
    assert problems[0].startswith(str(tmp_path / where)) or problems[0].startswith(where), got
    for part in expected:
        assert part in problems[0], got


def test_the_example_of_the_readme_is_what_the_check_prints(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    readme = (ROOT / "README.md").read_text()
    section = readme[readme.index("### A mistake in the configuration") :]
    shown = re.search(r"```text\n(.*?)\n```", section, flags=re.DOTALL)[1]
    monkeypatch.chdir(tmp_path)
    (tmp_path / "config").mkdir()
    text = CASES["float for an integer (issue 9)"][0](CONFIG_TEXT)
    got = message(tmp_path / "config", text)
    assert got == f"{config_checks.HEADER}\n{shown}"


def test_a_yaml_syntax_error_names_file_line_and_column(tmp_path: Path) -> None:
    text = replaced("  n_points: 400\n\nfig3", "  n_points: 400\n bad: [\n\nfig3")
    got = message(tmp_path, text)
    assert got is not None
    assert len(got.splitlines()) == 1
    assert got.startswith(f"{tmp_path / 'config.yaml'}:{line_of(text, ' bad: [')}:2: ")
    assert "YAML syntax error" in got


def test_a_missing_or_empty_file_is_told_in_one_line(tmp_path: Path) -> None:
    missing = config_checks.file_problem(tmp_path / "missing.yaml")
    assert missing == f"{tmp_path / 'missing.yaml'}: no such configuration file" + (
        f" (working directory {Path.cwd()})"
    )
    (tmp_path / "empty.yaml").write_text("# nothing\n")
    assert "got an empty file" in str(config_checks.file_problem(tmp_path / "empty.yaml"))


def test_many_mistakes_are_listed_in_file_order_and_cut_short(tmp_path: Path) -> None:
    text = CONFIG_TEXT
    for key in ("dpi: 200", "tilt: 0.35", "n_points: 2000", "n_points: 300", "n_grid: 200", "size"):
        value = key.split(": ")[1] if ": " in key else "320"
        key = key if ": " in key else f"{key}: {value}"
        text = replaced(key, key.replace(value, f'"{value}"'), text)
    lines = str(message(tmp_path, text)).splitlines()
    assert len(lines) == 1 + config_checks.MAX_PROBLEMS + 1
    assert lines[-1] == "(and 1 more)"
    numbers = [int(re.search(r"config\.yaml:(\d+):", line)[1]) for line in lines[1:-1]]
    assert numbers == sorted(numbers)


def test_a_value_given_on_the_command_line_is_told_so(tmp_path: Path) -> None:
    """A value that is not what the files give came from --config (Snakemake reads the values
    inside a section given there as text): the message names the command line, not the
    line of config.yaml that the command line overrode."""
    path = tmp_path / "config.yaml"
    path.write_text(CONFIG_TEXT)
    config = yaml.safe_load(CONFIG_TEXT)
    config["fig2_spectrum"]["n_points"] = "1e-4"  # --config 'fig2_spectrum={"n_points": 1e-4}'
    config["style"]["dpi"] = 10
    lines = str(config_checks.config_problem(config, [path])).splitlines()[1:]
    assert len(lines) == 2, lines
    assert all(line.startswith("--config (command line): ") for line in lines), lines
    assert "fig2_spectrum.n_points = '1e-4' is text" in lines[1]
    assert "pass it with --configfile" in lines[1]
    assert "style.dpi = 10" in lines[0]
    # a mistake of the file beside one of the command line: each told where it was made
    config["style"]["dpi"] = 200
    text = replaced("  tilt: 0.35", "  tilt: 2.0")
    path.write_text(text)
    config["fig1_schematic"]["tilt"] = 2.0
    lines = str(config_checks.config_problem(config, [path])).splitlines()[1:]
    assert lines[0].startswith(f"{path}:{line_of(text, 'tilt: 2.0')}: fig1_schematic.tilt"), lines
    assert lines[1].startswith("--config (command line): fig2_spectrum.n_points"), lines


def test_the_file_that_sets_a_bad_value_is_named(tmp_path: Path) -> None:
    """With --configfile, a value is told where it was written: in the file that overrides."""
    base = tmp_path / "config.yaml"
    base.write_text(CONFIG_TEXT)
    mine = tmp_path / "mine.yaml"
    mine.write_text("# my changes\nfig2_spectrum:\n  n_points: 400.0\n")
    config = yaml.safe_load(CONFIG_TEXT)
    config["fig2_spectrum"]["n_points"] = 400.0
    got = config_checks.config_problem(config, [base, mine])
    assert f"{mine}:3: fig2_spectrum.n_points = 400.0" in str(got)


def test_the_fewest_frames_count_the_parameters_of_the_larger_fit() -> None:
    """MIN_FRAMES is two frames per parameter of the larger model of turntable fit, its noise
    variance included; the fits need fewer (more coordinates than parameters) and so does
    Fig. 8 (a positive number of residual degrees of freedom): the margin of the check."""
    assert max(fit.n_parameters(m) for m in fit.MODELS) == config_checks.FIT_PARAMETERS
    assert config_checks.MIN_FRAMES == 2 * (config_checks.FIT_PARAMETERS + 1)
    assert 2 * 3 - config_checks.FIT_PARAMETERS < 0  # the 3 frames of issue 9's 0.01 s
    # at least what turntable.fit needs to select a model, where it says so
    assert getattr(fit, "min_frames", lambda: 0)() <= config_checks.MIN_FRAMES
    # the count is turntable.film's
    for fps, duration in [(240.0, 0.01), (240.0, 10.0), (30.0, 0.5), (29.97, 1.0 / 29.97)]:
        camera = turntable.film.Camera(fps, 1e-4, duration)
        n = turntable.film.frame_times(camera).size
        assert config_checks.film_frames(fps, duration) == n, (fps, duration)


def test_a_film_ends_where_its_rolling_ball_is_representable() -> None:
    """The synthetic films of the rolling model are checked with turntable.rolling.solve at
    the film's last frame (in t Omega), the limit found here by bisection."""
    config = pipeline.base_config()
    rolling_film = {"name": "rolling", "model": "rolling_resistance", "coefficient": 0.02}
    config["synthetic_film"]["films"] = [
        {**rolling_film, "seed": 1},
        {**rolling_film, "name": "other", "seed": 2},
    ]
    config["fig8_measurability"]["mu0_range"] = [1.0e3, 1.0e4]  # slow growth there
    film = config["film"]
    film.update(rpm=10000.0, fps=10.0)
    omega = turntable.film.rpm_to_omega(film["rpm"])
    z0 = turntable.no_slip_state(turntable.film.rig_from_config(film).state0, film["k"])
    low, high = 1.0, 1.0e6  # t Omega
    for _ in range(60):
        mid = (low * high) ** 0.5
        try:
            rolling.solve(z0, [mid], 0.02, film["k"])
            low = mid
        except ValueError:
            high = mid
    film["duration_s"] = 1.01 * high / omega
    (problem,) = config_checks.problems(config)
    assert problem.at == ("film", "duration_s")
    assert "too late for the rolling ball of synthetic film 'rolling'" in problem.text
    film["duration_s"] = 0.99 * low / omega
    assert config_checks.problems(config) == []


# --------------------------------------------------------------------------- checked before
def test_a_configuration_that_passed_is_not_checked_again_until_anything_changes(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The record of config_checks.CheckRecord skips the checks of a configuration that passed,
    unchanged; a change of the configuration, of a file or of what the checks read misses it,
    and a refused configuration is never recorded."""
    path = tmp_path / "config.yaml"
    path.write_text(CONFIG_TEXT)
    record = tmp_path / ".snakemake" / "config_checks.ok"
    config = yaml.safe_load(CONFIG_TEXT)

    def check(config: dict[str, Any]) -> tuple[bool, str | None]:
        """(whether the record was used, the message)"""
        checks = config_checks.CheckRecord([path], record)
        return checks.checked(config), config_checks.workflow_problem(config, [path], checks)

    assert check(config) == (False, None)
    assert record.is_file()
    assert check(config) == (True, None)
    assert config_checks.CheckRecord([path], record).files_checked()
    # a value of --config (or of another file), 400.0 for 400: checked, refused, not recorded
    bad = yaml.safe_load(CONFIG_TEXT)
    bad["fig2_spectrum"]["n_points"] = 400.0
    used, message = check(bad)
    assert not used
    assert "fig2_spectrum.n_points = 400.0 is not an integer" in str(message)
    assert check(bad)[0] is False
    assert check(config) == (True, None)
    # a comment in the file, or a change of the schema or of the package: checked again
    path.write_text(CONFIG_TEXT + "# a comment\n")
    assert not config_checks.CheckRecord([path], record).files_checked()
    assert check(config) == (False, None)
    read = list(config_checks._what_the_checks_read())
    assert ROOT / "workflow/schemas/config.schema.yaml" in read
    assert ROOT / "src/turntable/solution.py" in read
    assert ROOT / "src/turntable/claims/params.schema.yaml" in read
    monkeypatch.setattr(config_checks, "_what_the_checks_read", lambda: iter(read[:-1]))
    assert check(config)[0] is False


# --------------------------------------------------------------------------- time bounds
def _fig4(spans: list[list[float]], mu0: list[float]) -> dict[str, Any]:
    config = pipeline.base_config()
    config["fig4_trajectories"].update(mu0=mu0, t_span=spans)
    return config


def test_each_time_span_is_checked_against_its_own_mu0_with_max_time() -> None:
    """Span i pairs with mu0[i]; the bound is turntable.max_time of that mu0, k and state."""
    state, k = pipeline.base_config()["fig4_trajectories"]["state"], 0.4
    limit = {m: float(turntable.max_time(m, k, state)) for m in (0.3, 1.0)}
    assert limit[0.3] < limit[1.0]
    # the second span ends after the first mu0's limit: representable, since it pairs with
    # 1.0 (a figure could not show it: test_a_drawn_span_resolves_its_turns_and_growth)
    ok = _fig4([[0.0, 0.999 * limit[0.3]], [0.0, 0.999 * limit[1.0]]], [0.3, 1.0])
    assert config_checks.solution_time_problems(ok) == []
    bad = _fig4([[0.0, 1.001 * limit[0.3]], [0.0, 20.0]], [0.3, 1.0])
    (problem,) = config_checks.problems(bad)
    assert problem.at == ("fig4_trajectories", "t_span", 0)
    assert f"after t = {limit[0.3]:.6g}" in problem.text
    assert "mu0 = 0.3," in problem.text


def _drawn(section: str, **values: Any) -> list[str]:
    """The texts of the problems of the project's configuration with ``values`` in
    ``section`` (only the checks of drawn spans find any)."""
    config = yaml.safe_load(CONFIG_TEXT)
    config[section].update(values)
    found = config_checks.problems(config)
    assert found == config_checks.drawing_problems(config)
    return [problem.text for problem in found]


def test_a_drawn_span_resolves_its_turns_and_growth() -> None:
    """A span that is representable but that no figure can show is refused: too few points
    per turn of the spiral (beta of turntable.spectrum), or too much growth (alpha1 t_end).
    Fig. 4's last span [0, 1.0e+5] for mu0 = 10 passed the bounds and drew 2000 points over
    4500 turns with axes at 1e101."""
    spans = [[0.0, 45.0], [0.0, 35.0], [0.0, 45.0], [0.0, 70.0], [0.0, 1.0e5]]
    fig4 = _drawn("fig4_trajectories", t_span=spans)
    beta = float(turntable.spectrum(10.0, 0.4).beta)
    turns = beta * 1.0e5 / (2 * np.pi)
    assert len(fig4) == 2
    assert fig4[0].startswith(
        "fig4_trajectories.t_span[4] = [0, 100000], drawn at fig4_trajectories.n_points = 2000 "
        f"points, holds {turns:.4g} turns of the slipping ball (mu0 = 10): 0.44 points per turn;"
        f" expected at least {config_checks.MIN_POINTS_PER_TURN} per turn"
    )
    assert fig4[1].startswith(
        "fig4_trajectories.t_span[4] = [0, 100000]: by t = 100000, the slipping ball "
        "(mu0 = 10) has grown by e^(alpha1 t) = 10^101"
    )
    alpha1 = float(turntable.spectrum(10.0, 0.4).alpha1)
    assert fig4[1].endswith(f"t_end <= {np.log(config_checks.MAX_GROWTH) / alpha1:.4g}")
    # Fig. 3: too few points alone (one span for both mu0, the faster one named), then growth
    (fig3,) = _drawn("fig3_modal_terms", n_points=10)
    assert "holds 0.3591 turns of the slipping ball (mu0 = 1): 25 points per turn" in fig3
    assert "n_points >= 12," in fig3
    assert _drawn("fig3_modal_terms", n_points=12) == []
    (fig3,) = _drawn("fig3_modal_terms", t_span=[0.0, 200.0], n_points=5000)
    assert "by t = 200, the slipping ball (mu0 = 0.1) has grown" in fig3
    # Fig. 6: its layer is drawn on a log time axis: the growth alone
    (fig6,) = _drawn("fig6_limit", layer_t_span=[1.0e-4, 8000.0], n_points=2)
    assert fig6.startswith("fig6_limit.layer_t_span = [0.0001, 8000]: by t = 8000")
    # Fig. 7: the rolling ball turns faster than the slipping one, and is named
    (fig7,) = _drawn("fig7_rolling_resistance", t_span=[0.0, 500.0], n_points=300)
    assert "turns of the rolling ball (delta = " in fig7
    assert "n_points >= " in fig7


def test_the_project_spans_are_drawn_readably() -> None:
    """The default configuration passes with room: every drawn span at least twice the
    fewest points per turn, and a growth far below the bound."""
    config = yaml.safe_load(CONFIG_TEXT)
    strict = {"MIN_POINTS_PER_TURN": 2 * config_checks.MIN_POINTS_PER_TURN, "MAX_GROWTH": 1.0e3}
    saved = {name: getattr(config_checks, name) for name in strict}
    try:
        for name, value in strict.items():
            setattr(config_checks, name, value)
        assert config_checks.drawing_problems(config) == []
    finally:
        for name, value in saved.items():
            setattr(config_checks, name, value)


def test_a_range_of_mu0_is_checked_at_the_peak_of_alpha1() -> None:
    """The study's span must stay below max_time at the worst mu0 of its range."""
    config = pipeline.base_config()
    study = config["study"]
    k = 0.4
    peak = float(turntable.alpha1_peak(k).mu0)
    worst = float(turntable.max_time(peak, k, study["state"]))
    ends = [float(turntable.max_time(m, k, study["state"])) for m in (peak / 3, 3 * peak)]
    assert min(ends) > 1.05 * worst  # the ends of the range alone would not catch it
    study.update(k=[k], mu0_range=[peak / 3, 3 * peak], t_span=[0.0, 1.001 * worst])
    (problem,) = config_checks.problems(config)
    assert problem.at == ("study", "t_span")
    study["t_span"] = [0.0, 0.99 * worst]
    assert config_checks.problems(config) == []


def test_a_state_costs_less_than_half_the_bound_of_the_growth_alone() -> None:
    """What the sampling of a range of mu0 assumes: for every allowed mu0, k and state,
    max_time(mu0, k, z0) >= max_time(mu0, k) / 2 (the solution's size is below 1e154)."""
    mu0 = np.geomspace(*_bounds(SCHEMA["$defs"]["mu0"]), 25)
    k = np.geomspace(*_bounds(SCHEMA["$defs"]["k"]), 7)
    big = SCHEMA["$defs"]["state"]["items"]["maximum"]
    states = [[big] * 6, [big, -big, big, -big, big, -big], [0.0, 0.0, big, 0.0, 0.0, 0.0]]
    for m in mu0:
        for kk in k:
            alone = float(turntable.max_time(m, kk))
            for z0 in states:
                assert float(turntable.max_time(m, kk, z0)) >= alone / 2, (m, kk, z0)


def test_the_rolling_ball_of_fig7_is_checked_with_its_own_growth() -> None:
    config = pipeline.base_config()
    fig7 = config["fig7_rolling_resistance"]
    fig7["comparison"] = "equal_coefficient"
    z0 = turntable.no_slip_state(fig7["state"], fig7["k"])
    slipping = float(turntable.max_time(fig7["mu0"], fig7["k"], z0))
    delta = float(rolling.matched_delta(fig7["mu0"], fig7["k"], "equal_coefficient"))
    with pytest.raises(ValueError, match=r"t must be (?:<=|at most) ([0-9.e+]+)") as info:
        rolling.solve(z0, [slipping], delta, fig7["k"])
    limit = float(re.search(r"(?:<=|at most) ([0-9.e+]+)", str(info.value))[1])
    fig7["t_span"] = [0.0, 1.01 * limit]
    (problem,) = config_checks.problems(config)
    assert "rolling ball" in problem.text
    fig7["t_span"] = [0.0, 0.99 * limit]
    assert config_checks.solution_time_problems(config) == []


def _bounds(prop: dict[str, Any]) -> tuple[float, float]:
    return prop["minimum"], prop["maximum"]


def test_the_bounds_of_mu0_and_k_keep_the_model_finite() -> None:
    """At the corners of the schema's bounds, every curve a figure draws is finite."""
    mu0 = np.array(_bounds(SCHEMA["$defs"]["mu0"]))
    k = np.array(_bounds(SCHEMA["$defs"]["k"]))[:, None]
    assert (_bounds(CLAIMS_SCHEMA["$defs"]["mu0"]), _bounds(CLAIMS_SCHEMA["$defs"]["k"])) == (
        tuple(mu0),
        tuple(k.ravel()),
    )
    with np.errstate(all="raise"):
        s = turntable.spectrum(mu0, k)
        values = [s.alpha1, s.alpha2, s.beta, turntable.log_damping_ratio(mu0, k)]
        values += [turntable.log_growth_per_turn(mu0, k), turntable.alpha1_peak(k).mu0]
        values += list(turntable.small_friction_expansion(mu0, k))
        values += list(turntable.large_friction_expansion(mu0, k))
        for kk in k.ravel():
            for comparison in SCHEMA["properties"]["fig7_rolling_resistance"]["properties"][
                "comparison"
            ]["enum"]:
                delta = rolling.matched_delta(mu0, kk, comparison)
                values += [delta, rolling.log_growth_per_turn(delta, kk)]
    assert all(np.all(np.isfinite(v)) for v in values)


def test_one_no_slip_period_is_representable_for_every_allowed_k() -> None:
    """Fig. 6 (a), (b) solve over one period 2 pi (k+1)/k, which has no time key to check:
    over the schema's k, at the fastest-growing mu0 and the largest allowed state, the
    solution stays representable (so the figure cannot fail whatever the configuration).
    """
    k_low, k_high = _bounds(SCHEMA["$defs"]["k"])
    big = SCHEMA["$defs"]["state"]["items"]["maximum"]
    for k in np.geomspace(k_low, k_high, 61):
        peak = float(turntable.alpha1_peak(k).mu0)
        period = float(turntable.nonholonomic_period(k))
        assert float(turntable.max_time(peak, k, [big] * 6)) > period, k


# --------------------------------------------------------------------------- the schema
LEAVES = [
    (section, key)
    for section in SCHEMA["properties"]
    for key in config_checks.key_schema((section,))["properties"]
]


def unbounded(at: tuple[str | int, ...]) -> list[str]:
    """What the schema of ``at`` lacks to give a type and bounds (items included)."""
    prop = config_checks.key_schema(at)
    kind = prop.get("type")
    if kind in ("number", "integer"):
        low = {"minimum", "exclusiveMinimum"} & set(prop)
        high = {"maximum", "exclusiveMaximum"} & set(prop)
        return [] if low and high else [f"{at}: bounds"]
    if kind == "array":
        missing = [f"{at}: {k}" for k in ("minItems", "maxItems", "items") if k not in prop]
        return missing or unbounded((*at, 0))
    if kind == "object":  # an entry of a list: each of its keys
        props = prop.get("properties", {})
        if prop.get("additionalProperties") is not False or not props:
            return [f"{at}: keys"]
        return [p for key in props for p in unbounded((*at, key))]
    if kind == "string":
        return [] if "enum" in prop or {"pattern", "maxLength"} <= set(prop) else [f"{at}: form"]
    return [f"{at}: type {kind!r}"]


@pytest.mark.parametrize("at", LEAVES, ids=".".join)
def test_every_key_has_type_bounds_description_and_a_valid_default(at: tuple[str, ...]) -> None:
    prop = config_checks.key_schema(at)
    assert unbounded(at) == []
    assert len(prop.get("description", "")) > 10
    assert "default" in prop


def reference_differences(path: Path, shown: str = "config/config.yaml") -> str | None:
    """Why the configuration file at ``path`` is not the schema's defaults, or None.

    The project's configuration file holds its reference values, which are the `default:`
    of each key of the schema: one value per key, however the two are read. The message
    names each key that differs (file and line, both values) and the two ways forward.
    """
    config = yaml.safe_load(path.read_text())
    lines = config_checks.Sources([path]).lines[0]
    differ = []
    for section in dict.fromkeys([*SCHEMA["properties"], *config]):
        props = config_checks.key_schema((section,)).get("properties", {})
        if section not in config or section not in SCHEMA["properties"]:
            where = "the schema" if section not in config else shown
            differ.append(f"  section {section} is only in {where}")
            continue
        for key in dict.fromkeys([*props, *config[section]]):
            if key not in config[section] and section == "claims":
                continue  # a key of the claims checks left out takes the schema's default
            value = config[section].get(key, "(missing)")
            default = props.get(key, {}).get("default", "(no such key)")
            if json.dumps(value) != json.dumps(default):  # type included: 400 is not 400.0
                line = lines.get((section, key), lines.get((section,), 0))
                differ.append(
                    f"  {shown}:{line}: {section}.{key} = {json.dumps(value)}; "
                    f"the schema's default: {json.dumps(default)}"
                )
    if not differ:
        return None
    return "\n".join(
        [
            f"{shown} holds the project's reference values, which are the `default:` of each "
            "key in workflow/schemas/config.schema.yaml; these differ:",
            *differ,
            "Either",
            f"  - build with values of your own: restore {shown} (git checkout {shown}), put "
            "the keys you change in a file of your own with the same layout, and run "
            "`make CONFIGFILE=my.yaml` (its values go over those of config/config.yaml); or",
            "  - change the project's reference values: write each value above as the "
            "`default:` of its key in workflow/schemas/config.schema.yaml too.",
        ]
    )


def test_the_configuration_file_holds_the_defaults_of_the_schema() -> None:
    """config/config.yaml and the schema's `default:` entries give the same values (type
    included), so that the two cannot drift apart; keys of the claims checks left out take
    the schema's default, the one place they live."""
    problem = reference_differences(ROOT / "config" / "config.yaml")
    if problem:
        pytest.fail(problem, pytrace=False)


def test_a_reference_value_changed_in_one_place_is_told_with_the_ways_forward(
    tmp_path: Path,
) -> None:
    """The README's example of a change (the last mu0 of Fig. 4) made in config/config.yaml
    alone: the message names the key, its line and both values, and says what to do."""
    path = tmp_path / "config.yaml"
    old = "  mu0: [0.02, 0.0793, 0.3, 1.0, 10.0]\n"
    path.write_text(replaced(old, old.replace("10.0]", "5.0]")))
    problem = reference_differences(path)
    assert problem is not None
    line = line_of(CONFIG_TEXT, old.rstrip())
    assert (
        f"config/config.yaml:{line}: fig4_trajectories.mu0 = [0.02, 0.0793, 0.3, 1.0, 5.0]; "
        "the schema's default: [0.02, 0.0793, 0.3, 1.0, 10.0]"
    ) in problem
    assert len([x for x in problem.splitlines() if "fig4_trajectories" in x]) == 1
    assert "make CONFIGFILE=my.yaml" in problem
    assert "git checkout config/config.yaml" in problem
    assert "`default:` of its key in workflow/schemas/config.schema.yaml" in problem
    # a count written as a float differs too, and a missing key is named
    text = replaced("  n_points: 400\n\nfig3", "  n_points: 400.0\n\nfig3")
    path.write_text(replaced("  mu0_layer: [10.0, 100.0, 1000.0]\n", "", text))
    problem = reference_differences(path)
    assert "fig2_spectrum.n_points = 400.0; the schema's default: 400" in problem
    assert 'fig6_limit.mu0_layer = "(missing)"' in problem


def _keys(at: tuple[str | int, ...]) -> list[tuple[str | int, ...]]:
    """Every key below ``at``, also the keys of the entries of a list of sections."""
    prop = config_checks.key_schema(at)
    if prop.get("type") == "array" and config_checks.key_schema((*at, 0)).get("properties"):
        return _keys((*at, 0))
    found = []
    for key in prop.get("properties", {}):
        found += [(*at, key), *_keys((*at, key))]
    return found


def test_every_property_of_the_schema_has_type_description_and_default() -> None:
    keys = [key for section in SCHEMA["properties"] for key in _keys((section,))]
    assert ("synthetic_film", "films", 0, "seed") in keys
    for at in keys:
        prop = config_checks.key_schema(at)
        assert {"type", "description", "default"} <= set(prop), at


def test_the_defaults_make_a_valid_configuration() -> None:
    defaults = {
        section: {key: config_checks.key_schema((section, key))["default"] for key in props}
        for section in SCHEMA["properties"]
        for props in [config_checks.key_schema((section,))["properties"]]
    }
    assert config_checks.problems(defaults) == []
    bad = {**defaults, "style": {"dpi": 1}}
    assert config_checks.problems(bad) != []


def test_every_section_requires_all_its_keys_and_refuses_others() -> None:
    for section in SCHEMA["properties"]:
        prop = config_checks.key_schema((section,))
        assert prop["type"] == "object", section
        assert prop["additionalProperties"] is False, section
        assert prop.get("description"), section
        if section != "claims":  # a claims key left out takes the package's default
            assert sorted(prop["required"]) == sorted(prop["properties"]), section
    assert sorted(SCHEMA["required"]) == sorted(SCHEMA["properties"])


@pytest.mark.parametrize(
    "at", [at for at in LEAVES if at[0] != "claims" and re.search(r"(^|_)t_(span|end)$", at[1])]
)
def test_every_time_key_of_a_figure_is_checked_against_max_time(at: tuple[str, ...]) -> None:
    """A key named t_span, *_t_span or t_end says which mu0, k and state it is solved for."""
    rule = config_checks.key_schema(at).get("x-solution-times")
    assert rule, f"{'.'.join(at)} has no x-solution-times"
    keys = config_checks.key_schema(at[:1])["properties"]
    for role in ("mu0", "k", "state"):
        assert rule[role] in keys, (role, rule[role])
    if "rolling" in rule:
        assert "enum" in keys[rule["rolling"]]


# --------------------------------------------------------------------------- end to end
@pytest.fixture(scope="session")
def good_build(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> Path:
    """The clean build of tests/test_pipeline.py (shared, built once per test run)."""
    workdir, record = build_once(
        shared_dir(tmp_path_factory, worker_id), "pipeline-clean", pipeline._clean_build
    )
    assert record["returncode"] == 0, record["log"]
    return workdir


def snapshot(workdir: Path) -> dict[str, tuple[str, int]]:
    """Bytes (hash) and modification time of every file but the configuration."""
    return {
        str(p.relative_to(workdir)): (
            sha256(p),
            p.stat().st_mtime_ns,
        )
        for p in sorted(workdir.rglob("*"))
        if p.is_file() and p.relative_to(workdir).parts[0] not in ("config", ".snakemake")
    }


BASE_TEXT = dumped(pipeline.base_config())

# (edit of the cut-down configuration, texts of the message): the cases of issue 9
END_TO_END = {
    "n_points: 400.0": (
        lambda t: replaced("  n_points: 200\nfig3", "  n_points: 400.0\nfig3", t),
        ["config/config.yaml:", "fig2_spectrum.n_points = 400.0 is not an integer", "write 400"],
    ),
    "t_span to 1e5": (
        lambda t: t.replace("  - - 0.0\n    - 20.0\n", "  - - 0.0\n    - 1.0e+5\n", 1),
        ["fig4_trajectories.t_span[0] ends at t = 100000", "turntable.max_time"],
    ),
    # representable, but 2000 points over 4500 turns and axes at 1e101 went into the article
    "fig4's last span to 1e5 for mu0 = 10": (
        lambda t: replaced(
            "  - 1.0\n  t_span:\n  - - 0.0\n    - 20.0\n  - - 0.0\n    - 30.0\n",
            "  - 10.0\n  t_span:\n  - - 0.0\n    - 20.0\n  - - 0.0\n    - 1.0e+5\n",
            t,
        ),
        [
            "config/config.yaml:",
            "fig4_trajectories.t_span[1] = [0, 100000], drawn at fig4_trajectories.n_points",
            "expected at least 30 per turn",
            "has grown by e^(alpha1 t) = 10^101",
        ],
    ),
    "misspelt section": (
        lambda t: replaced("fig2_spectrum:", "fig2_spectrm:", t),
        ["unknown section 'fig2_spectrm'; did you mean 'fig2_spectrum' (missing)?"],
    ),
    "YAML syntax error": (
        lambda t: replaced("fig3_modal_terms:\n", "fig3_modal_terms:\n bad: [\n", t),
        ["config/config.yaml:", "YAML syntax error"],
    ),
    "1e-4": (
        lambda t: replaced("  - 0.0001\n  - 1000.0\n", "  - 1e-4\n  - 1000.0\n", t),
        ["fig2_spectrum.mu0_range[0] = '1e-4' is text", "write 1.0e-4"],
    ),
    "missing key": (
        lambda t: replaced("  n_grid: 20\n", "", t),
        ["missing key 'n_grid' in fig7_rolling_resistance"],
    ),
    # Fig. 8 and the fits ended in "math domain error", and the good Fig. 8 was deleted
    "film of 3 frames": (
        lambda t: replaced(
            "  fps: 30.0\n", "  fps: 240.0\n", replaced("ion_s: 10.0", "ion_s: 0.01", t)
        ),
        ["config/config.yaml:", "film.duration_s = 0.01 s at film.fps = 240 frames/s gives 3"],
    ),
    # (edit, texts of the message, more arguments of snakemake)
    "a value of --config": (
        lambda t: t,
        ["--config (command line): fig2_spectrum.n_points = '1e-4'", "--configfile"],
        ["--config", 'fig2_spectrum={"n_points": 1e-4}'],
    ),
}


@pytest.mark.parametrize("case", list(END_TO_END))
def test_snakemake_refuses_before_any_job_and_keeps_the_outputs(
    good_build: Path, tmp_path: Path, case: str
) -> None:
    edit, expected, *args = END_TO_END[case]
    workdir = tmp_path / "copy"
    shutil.copytree(good_build, workdir, symlinks=True)  # copy2 keeps the mtimes
    before = snapshot(workdir)
    assert any(name.startswith("figures/") for name in before)
    text = edit(BASE_TEXT)
    (workdir / "config" / "config.yaml").write_text(text)

    proc = pipeline.run_snakemake(workdir, "figures", *(args[0] if args else []))

    out = (proc.stdout + proc.stderr).strip()
    assert proc.returncode != 0
    assert len(out.splitlines()) <= MAX_OUTPUT_LINES, out
    for part in expected:
        assert part in out, out
    if args:  # told as the command line's, not as the line of the file it overrides
        assert "config/config.yaml:" not in out, out
    assert "Traceback" not in out
    assert snapshot(workdir) == before


# --------------------------------------------------------------------------- make CONFIGFILE=
def test_a_missing_or_broken_configfile_is_told_by_the_check_make_runs_first(
    tmp_path: Path,
) -> None:
    """`snakemake --configfile` reads the file before the Snakefile (a traceback for a missing
    file, no line for a syntax error); `make CONFIGFILE=...` checks it first."""
    script = ROOT / "workflow" / "config_checks.py"
    bad = tmp_path / "bad.yaml"
    bad.write_text("fig2_spectrum:\n  n_points: 400\n bad: [\n")
    for path, expected in [
        (tmp_path / "missing.yaml", "missing.yaml: no such configuration file"),
        (bad, f"{bad}:3:2: YAML syntax error"),
    ]:
        proc = subprocess.run(
            [sys.executable, str(script), str(path)], capture_output=True, text=True, check=False
        )
        assert proc.returncode == 1
        assert proc.stdout == ""
        assert len(proc.stderr.splitlines()) == 1, proc.stderr
        assert expected in proc.stderr
    plan = subprocess.run(
        ["make", "-n", "-C", str(ROOT), "CONFIGFILE=my.yaml", "all", "notebooks", "report"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    runs = [line for line in plan.splitlines() if "snakemake" in line]
    assert runs
    for line in runs:
        check = line.index("config_checks.py my.yaml &&")
        assert check < line.index("snakemake --configfile my.yaml"), line


def test_the_readme_tells_why_make_configfile_is_the_supported_route(tmp_path: Path) -> None:
    """Snakemake reads a --configfile before the workflow: run directly on a missing file it
    still ends in a traceback, which the README gives as the reason to pass a file of one's
    own with `make CONFIGFILE=` (when a Snakemake update tells it in a line, the README's
    reason is to be revised)."""
    readme = (ROOT / "README.md").read_text()
    assert "**`make CONFIGFILE=my.yaml` is the supported way to pass a file of your own**" in readme
    assert "`snakemake --configfile my.yaml` run directly answers a missing file with a" in readme
    proc = subprocess.run(
        [pipeline.SNAKEMAKE, "--dry-run", "--configfile", str(tmp_path / "missing.yaml")],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=False,
    )
    assert proc.returncode != 0
    assert "Traceback" in proc.stdout + proc.stderr
