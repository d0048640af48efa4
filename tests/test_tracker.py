"""Tracker's exports read as Tracker writes them (`turntable.tracker`), and fits that never
claim too much: a film that neither model describes is never decisive."""

from __future__ import annotations

import json
import subprocess

import numpy as np
import pytest

from turntable import cli, film, fit, tracker

SETUP = film.Setup(0.005, film.rpm_to_omega(100.0 / 3.0), 0.4, (0.0, 0.0))


def _film(n: int = 120) -> film.Film:
    rng = np.random.default_rng(4)
    t = np.arange(n) / 30.0
    xy = fit.positions("slipping", 2.0, [10.0, 0.0, 0.0, 0.0, 0.0, 0.0], t, SETUP)
    xy += 2e-4 * rng.standard_normal(xy.shape)
    return film.Film(t, xy[:, 0], xy[:, 1])


def _single(data: film.Film, delimiter: str, unit: float = 1.0) -> str:
    """One track as Tracker exports it: name, columns (more than t, x, y), E notation, and
    an empty cell at the end of the last rows (a column longer than the others)."""
    lines = ["mass_A", delimiter.join(["t", "x", "y", "v_{x}"])]
    for i, (t, x, y) in enumerate(zip(data.t, data.x / unit, data.y / unit, strict=True)):
        v = "" if i >= data.t.size - 2 else f"{1.5:.9E}"
        lines.append(delimiter.join([f"{t:.9E}", f"{x:.9E}", f"{y:.9E}", v]))
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize(
    "delimiter",
    [
        pytest.param("\t", id="tab"),
        pytest.param(",", id="comma"),
        pytest.param(";", id="semicolon"),
        pytest.param(" ", id="space"),
    ],
)
def test_single_track(tmp_path, delimiter) -> None:
    data = _film()
    path = tmp_path / "mass_A.txt"
    path.write_text(_single(data, delimiter))
    assert tracker.is_tracker(path)
    got, name = tracker.read_tracker(path)
    assert name == "mass_A"
    np.testing.assert_allclose(got.x, data.x, rtol=1e-8)
    np.testing.assert_allclose(got.t, data.t, rtol=1e-8, atol=1e-12)


def test_multi_track_with_gaps_and_units(tmp_path) -> None:
    """Tracker 6's form of several tracks: #multi:, the names above their columns; cm."""
    data = _film()
    rows = [
        "#multi:",
        "\t".join(["mass_A", "", "", "mass_B", "", ""]),
        "\t".join(["t", "x", "y", "t", "x", "y"]),
    ]
    for i, (t, x, y) in enumerate(zip(data.t, data.x * 100, data.y * 100, strict=True)):
        a = ["", "", ""] if i in (5, 6) else [f"{t:.9E}", f"{x:.9E}", f"{y:.9E}"]
        rows.append("\t".join([*a, f"{t:.9E}", "1.0E0", "2.0E0"]))
    path = tmp_path / "tracks.txt"
    path.write_text("\n".join(rows) + "\n")
    got, name = tracker.read_tracker(path, scale=tracker.UNITS["cm"])
    assert name == "mass_A"
    assert got.t.size == data.t.size - 2  # the frames without a point are gaps
    np.testing.assert_allclose(got.x, np.delete(data.x, [5, 6]), rtol=1e-8)
    other, name = tracker.read_tracker(path, "mass_B")
    assert name == "mass_B"
    assert np.all(other.x == 1.0)
    with pytest.raises(film.FilmError, match="no track 'mass_C'"):
        tracker.read_tracker(path, "mass_C")


def test_fit_reads_a_tracker_export_in_cm(tmp_path, capsys) -> None:
    data = _film()
    path = tmp_path / "mass_A.txt"
    path.write_text(_single(data, "\t", unit=0.01))
    code = cli.main(["fit", str(path), "--radius", "0.005", "--rpm", "33.3333333", "--units", "cm"])
    out, err = capsys.readouterr()
    assert code == 0
    assert "units calibrated in Tracker" in err
    res = json.loads(out)
    assert abs(res["slipping"]["mu0"] - 2.0) < 3 * res["slipping"]["mu0_stderr"]


def test_tracker_cell_not_a_number(tmp_path) -> None:
    path = tmp_path / "bad.txt"
    path.write_text("mass_A\nt\tx\ty\n0\t1.0E-2\t0\n1\tabc\t0\n")
    with pytest.raises(film.FilmError, match=r":4: 'abc' is not a number"):
        tracker.read_tracker(path)


# ------------------------------------------------------------- a film neither model describes
def _run(capsys, path) -> subprocess.CompletedProcess:
    code = cli.main(["fit", str(path), "--radius", "0.005", "--rpm", "33.3333333"])
    out, err = capsys.readouterr()
    return subprocess.CompletedProcess([], code, out, err)


@pytest.mark.parametrize(
    "kind",
    [pytest.param("straight", id="straight-line"), pytest.param("slowing", id="slowing-platter")],
)
def test_never_decisive_when_neither_model_describes_the_film(kind) -> None:
    """A ball running in a straight line (mu0 at the end of its range), and a slipping ball on
    a platter that slows down (residuals 10 times the noise, correlated): the AICc
    difference is large, but the selection is not decisive, and the warnings say why."""
    rng = np.random.default_rng(1)
    t = np.arange(0, 4, 1 / 60)
    if kind == "straight":
        xy = np.c_[0.03 + 0.01 * t, 0.01 + 0.002 * t]
    else:
        xy = fit.positions("slipping", 0.5, [10.0, 0, 0, 0, 0, 0], t - 0.08 * t**2, SETUP)
    data = film.Film(t, *(xy + 2e-4 * rng.standard_normal(xy.shape)).T)
    result = fit.fit_film(data, SETUP)
    assert result.decisive
    assert result.aicc_difference > 10
    out = fit.result_json(result, SETUP, data)
    assert out["selection"]["decisive"] is False
    assert "neither model describes the film" in out["selection"]["reason"]
    assert any("neither model" in w for w in out["warnings"])


def test_decisive_for_a_film_a_model_describes() -> None:
    data = _film(240)
    out = fit.result_json(fit.fit_film(data, SETUP), SETUP, data)
    assert out["selected"] == "slipping"
    assert out["selection"]["decisive"] is True
