"""A configuration is checked before any job runs: its schema (types, bounds, defaults) by
`turntable.config.validate`, what needs the model by `turntable.config.problems`; a mistake
is refused in one line per problem, with every built file left as it was."""

from __future__ import annotations

import copy
import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import turntable
from ci_build import ROOT, snakemake
from turntable import config as checks

SCHEMA = ROOT / "workflow" / "schemas" / "config.schema.yaml"


def filled(**sections: dict) -> dict:
    config = copy.deepcopy(sections)
    assert checks.validate(config, SCHEMA) == []
    return config


@pytest.fixture(scope="module")
def defaults() -> dict:
    return filled()


def test_the_defaults_are_a_valid_configuration(defaults: dict) -> None:
    assert checks.problems(defaults) == []
    assert defaults["fig2_spectrum"]["n_points"] == 400
    assert defaults["claims"]["k_paper"] == 0.4  # the claims' own schema, referred to


@pytest.mark.parametrize(
    ("section", "expected"),
    [
        pytest.param(
            {"fig2_spectrum": {"n_points": 400.0}},
            "fig2_spectrum.n_points: 400.0 is not of type 'integer'",
            id="float-count",
        ),
        pytest.param(
            {"fig2_spectrum": {"mu0_range": ["1e-4", 1.0]}},
            "fig2_spectrum.mu0_range[0]: '1e-4' is not of type 'number' "
            "(YAML reads it as text: write 1.0e-4)",
            id="yaml-text",
        ),
        pytest.param(
            {"film": {"fps": -3.0}},
            "film.fps: -3.0 is less than or equal to the minimum of 0",
            id="bound",
        ),
        pytest.param(
            {"fig2_spectrm": {}},
            "configuration: Additional properties are not allowed ('fig2_spectrm' was unexpected)",
            id="misspelt-section",
        ),
        pytest.param(
            {"fig7_rolling_resistance": {"comparison": "equal"}},
            "fig7_rolling_resistance.comparison: 'equal' is not one of",
            id="enum",
        ),
        pytest.param(
            {"claims": {"n_states": 4.0}},
            "claims.n_states: 4.0 is not of type 'integer'",
            id="claims-schema",
        ),
        pytest.param(
            {"animation": {"k": float("nan")}}, "animation.k: nan is not of type 'number'", id="nan"
        ),
        pytest.param(
            {"campaign": {"batch_size": 0}},
            "campaign.batch_size: 0 is less than the minimum of 1",
            id="batch-size",
        ),
    ],
)
def test_a_schema_mistake_is_one_line_with_the_key_and_what_is_expected(
    section: dict, expected: str
) -> None:
    (line,) = checks.validate(copy.deepcopy(section), SCHEMA)
    assert line.startswith(expected)


def with_values(defaults: dict, section: str, **values: object) -> dict:
    config = copy.deepcopy(defaults)
    config[section].update(values)
    return config


def test_a_span_ends_where_the_solution_is_representable(defaults: dict) -> None:
    limit = float(turntable.max_time(10.0, 0.4, [1.0, 1.0, 0.0, 0.0, 0.0, 1.0]))
    spans = [[0.0, 45.0], [0.0, 35.0], [0.0, 45.0], [0.0, 70.0], [0.0, 1.01 * limit]]
    (line,) = checks.problems(with_values(defaults, "fig4_trajectories", t_span=spans))
    assert line.startswith("fig4_trajectories.t_span[4] ends at t = ")
    assert line.endswith(f"expected t <= {limit:.6g}")
    ok = [[0.0, 45.0]] * 4 + [[0.0, 0.99 * limit]]
    assert not any(
        "leaves the doubles" in p
        for p in checks.problems(with_values(defaults, "fig4_trajectories", t_span=ok))
    )


def test_a_range_of_mu0_is_checked_at_the_peak_of_alpha1(defaults: dict) -> None:
    """The study's range [1e-3, 1e3] holds the peak of alpha1, the fastest growth."""
    peak = turntable.alpha1_peak(0.4)
    end = 1.001 * float(turntable.max_time(peak.mu0, 0.4, [1.0, 1.0, 0.0, 0.0, 0.0, 1.0]))
    config = with_values(defaults, "study", k=[0.4], mu0_range=[1e-3, 1e3], t_span=[0.0, end])
    (line,) = checks.problems(config)
    assert line.startswith(f"study.t_span ends at t = {end:g}")
    assert f"mu0 = {peak.mu0:.6g}" in line


def test_a_drawn_span_shows_the_growth_and_the_turns(defaults: dict) -> None:
    s = turntable.spectrum(1.0, 0.4)
    config = with_values(defaults, "fig3_modal_terms", mu0=[1.0], t_span=[0.0, 700.0])
    assert (
        f"fig3_modal_terms.t_span = [0, 700]: the motion grows by e^({float(s.alpha1):.3g} t), "
        f"more than 1e+06 by the end; expected t_end <= {np.log(1e6) / float(s.alpha1):.4g}"
    ) in checks.problems(config)
    t_start, t_end = defaults["fig3_modal_terms"]["t_span"]
    turns = float(s.beta) * (t_end - t_start) / (2 * np.pi)
    (line,) = checks.problems(with_values(defaults, "fig3_modal_terms", mu0=[1.0], n_points=10))
    assert f"holds {turns:.4g} turns" in line
    assert f"n_points >= {int(np.ceil(30 * turns)) + 1}" in line


def test_the_rolling_ball_of_fig7_is_checked_too(defaults: dict) -> None:
    config = with_values(defaults, "fig7_rolling_resistance", t_span=[0.0, 1.0e6])
    (line,) = checks.problems(config)
    assert line.startswith("fig7_rolling_resistance.t_span ")


@pytest.mark.parametrize(
    ("values", "expected"),
    [
        pytest.param(
            {"duration_s": 0.01},
            "film.duration_s = 0.01 s at film.fps = 240 gives 3 frames; expected from 16",
            id="few-frames",
        ),
        pytest.param(
            {"duration_s": 36000.0},
            "film.duration_s = 36000 s at film.fps = 240 gives 8640001 frames",
            id="many-frames",
        ),
        pytest.param(
            {"duration_s": 3000.0, "fps": 1.0},
            "film.duration_s = 3000 s at film.fps = 1 (t Omega = 10472) ends",
            id="late",
        ),
    ],
)
def test_a_film_has_enough_frames_and_ends_in_time(
    defaults: dict, values: dict, expected: str
) -> None:
    (line,) = checks.problems(with_values(defaults, "film", **values))
    assert line.startswith(expected)


def test_spans_increase_and_films_have_names_of_their_own(defaults: dict) -> None:
    films = [{"name": "a", "model": "slipping", "coefficient": 1.0, "seed": 1}] * 2
    config = with_values(defaults, "synthetic_film", films=films)
    config["fig2_spectrum"]["mu0_range"] = [10.0, 1.0]
    assert checks.problems(config) == [
        "fig2_spectrum.mu0_range = [10.0, 1.0]: expected [start, end] with start < end",
        "synthetic_film.films[1].name = 'a': expected a name of its own",
    ]


def test_the_animated_ball_stays_in_its_panels(defaults: dict) -> None:
    (line,) = checks.problems(with_values(defaults, "animation", t_end=400.0))
    assert line.startswith("animation.t_end = 400: the ball goes")
    assert line.endswith("expected at most animation.size / 2 - 1.5 = 158.5 R")


@pytest.mark.parametrize(
    "bad",
    [
        pytest.param("fig2_spectrum:\n  n_points: 400.0\nfilm:\n  fps: -3.0\n", id="schema"),
        pytest.param("fig4_trajectories:\n  t_span: [[0.0, 1.0e+5]]\n  mu0: [10.0]\n", id="model"),
    ],
)
def test_snakemake_refuses_before_any_job_and_keeps_the_outputs(
    clean_build: Path,
    tmp_path: Path,
    bad: str,
) -> None:
    clean_build = Path(shutil.copytree(clean_build, tmp_path / "copy", symlinks=True))
    before = {
        p: (p.stat().st_mtime_ns, p.read_bytes()) for p in (clean_build / "figures").iterdir()
    }
    (tmp_path / "bad.yaml").write_text(bad)
    proc = snakemake(clean_build, "--cores", "1", "--configfile", str(tmp_path / "bad.yaml"))
    assert proc.returncode != 0
    lines = (proc.stdout + proc.stderr).splitlines()
    assert len(lines) <= 25
    assert "Invalid configuration; nothing was run and no output was changed:" in lines
    assert {
        p: (p.stat().st_mtime_ns, p.read_bytes()) for p in (clean_build / "figures").iterdir()
    } == before


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        pytest.param(None, "No such file or directory", id="missing"),
        pytest.param("a: [1\n", "line 2, column 1", id="yaml-syntax"),
    ],
)
def test_make_reads_a_configfile_before_snakemake(
    tmp_path: Path, text: str | None, expected: str
) -> None:
    path = tmp_path / "my.yaml"
    if text is not None:
        path.write_text(text)
    proc = subprocess.run(
        ["make", "-s", f"CONFIGFILE={path}", "all"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=False,
        env=os.environ | {"MAKEFLAGS": ""},
    )
    assert proc.returncode != 0
    assert proc.stderr.startswith(f"{path}: ")
    assert expected in proc.stderr
