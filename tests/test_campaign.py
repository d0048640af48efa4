"""A campaign of films: the table's bad rows, one fit per film, the summary, and the
workflow that fits every good film whatever the others do."""

from __future__ import annotations

import csv
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import ci_build
from turntable.campaign import (
    CampaignError,
    Film,
    batches,
    fit_film,
    group_column,
    read_table,
    simulate,
    simulation,
    summary_row,
)

HEADER = "file,radius_m,k,rpm,platter_radius_m,surface,true_model,true_value,seed\n"
FILM_SECTION = ci_build.full_config()["film"] | {"fps": 60.0}


def _table(tmp_path: Path, *rows: str) -> Path:
    (tmp_path / "a.csv").write_text("t,x,y\n0,0,0\n")
    path = tmp_path / "table.csv"
    path.write_text(HEADER + "".join(r + "\n" for r in rows))
    return path


BAD_ROWS = {
    "radius not a number": ("a.csv,big,0.4,33,,felt,,,", "radius_m 'big' is not a number"),
    "negative k": ("a.csv,0.005,-0.4,33,,felt,,,", "k '-0.4' is not a positive number"),
    "no rpm for a film": ("a.csv,0.005,0.4,,,felt,,,", "rpm '' is not a number"),
    "file not found": ("b.csv,0.005,0.4,33,,felt,,,", "not found"),
    "no file": (",0.005,0.4,33,,felt,,,", "file is empty"),
    "synthetic without SYNTHETIC": (
        "results/x.csv,0.005,0.4,33,,felt,slipping,1,1",
        "must start with SYNTHETIC",
    ),
    "synthetic of no model": (
        "results/SYNTHETIC_x.csv,0.005,0.4,33,,felt,sliding,1,1",
        "true_model must be one of",
    ),
}


@pytest.mark.parametrize("what", BAD_ROWS)
def test_a_bad_row_is_named_with_its_number_and_the_others_are_kept(tmp_path, monkeypatch, what):
    row, message = BAD_ROWS[what]
    monkeypatch.chdir(tmp_path)
    films, bad = read_table(_table(tmp_path, "a.csv,0.005,0.4,33,,felt,,,", row).name)
    assert [f.name for f in films] == ["a"]
    assert films[0].labels == {"surface": "felt", "true_model": "", "true_value": "", "seed": ""}
    assert [b["row"] for b in bad] == [3]
    assert message in bad[0]["error"]


def test_two_rows_of_one_film_name(tmp_path):
    row = "a.csv,0.005,0.4,33,,felt,,,"
    films, bad = read_table(_table(tmp_path, row, row))
    assert len(films) == 1
    assert bad[0]["row"] == 3
    assert "earlier row" in bad[0]["error"]


@pytest.mark.parametrize("text", ["", "file,radius_m,k\na.csv,1,1\n"], ids=["empty", "no rpm"])
def test_a_table_without_the_columns_is_refused_in_one_line(tmp_path, text):
    (tmp_path / "t.csv").write_text(text)
    with pytest.raises(CampaignError, match=r"t.csv: no column .*rpm"):
        read_table(tmp_path / "t.csv")
    with pytest.raises(CampaignError, match="No such file"):
        read_table(tmp_path / "missing.csv")


@pytest.mark.parametrize(("model", "value"), [("slipping", 2.0), ("rolling_resistance", 0.01)])
def test_a_synthetic_film_is_fitted_back_to_its_truth(tmp_path, model, value):
    film = Film(2, "SYNTHETIC_a", str(tmp_path / "SYNTHETIC_a.csv"), 0.005, 0.4, 45.0, None,
                {"true_model": model, "true_value": str(value), "seed": "3"}, True)  # fmt: skip
    simulate(simulation(film, FILM_SECTION), film.path)
    assert "SYNTHETIC" in Path(film.path).read_text().splitlines()[0]
    result = fit_film(film.fit_options())
    row = summary_row({"name": film.name, "row": 2, "path": film.path, "labels": {}}, result)
    assert (row["status"], row["selected"], row["decisive"]) == ("fitted", model, True)
    assert abs(row["value"] - value) < 4 * row["stderr"]


def test_a_film_that_turntable_fit_refuses_gives_its_one_line(tmp_path):
    (tmp_path / "bad.csv").write_text("t,x,y\n0,0,zero\n")
    result = fit_film({"path": str(tmp_path / "bad.csv"), "radius": 0.005, "rpm": 33.0})
    assert list(result) == ["error"]
    assert "bad.csv" in result["error"]
    assert "\n" not in result["error"]
    row = summary_row({"name": "bad", "row": 5, "path": "bad.csv", "labels": {"s": "x"}}, result)
    assert row == {"film": "bad", "row": 5, "file": "bad.csv", "s": "x", "status": "failed",
                   "warnings": result["error"]}  # fmt: skip


def test_a_table_without_a_surface_column_is_grouped_by_its_first_label(tmp_path):
    (tmp_path / "a.csv").write_text("t,x,y\n0,0,0\n")
    head = "file,radius_m,k,rpm,platter_radius_m"
    (tmp_path / "t.csv").write_text(f"{head},ball,date\na.csv,0.005,0.4,33,,steel,may\n")
    films, bad = read_table(tmp_path / "t.csv")
    assert (len(films), bad) == (1, [])
    assert group_column(films, "") == "ball"
    assert group_column(films, "date") == "date"
    (tmp_path / "bare.csv").write_text(f"{head}\na.csv,0.005,0.4,33,\n")
    assert group_column(read_table(tmp_path / "bare.csv")[0], "") == ""  # not grouped
    with pytest.raises(CampaignError, match="no column surface"):
        read_table(tmp_path / "t.csv", group_by="surface")


def test_films_are_cut_in_batches_in_the_tables_order():
    names = [f"f{i}" for i in range(7)]
    assert batches(names, 3) == {"1": names[:3], "2": names[3:6], "3": names[6:]}
    assert batches(names, 7) == {"1": names}
    assert batches([], 3) == {}


def test_the_build_fits_every_good_film_and_names_the_others(clean_build, tmp_path):
    """Two films of the build, a bad row, a file turntable fit refuses, in a table without a
    column surface: snakemake succeeds, the summary has one row each, and the summary of
    make names the two failures."""
    copy = Path(shutil.copytree(clean_build, tmp_path / "copy", symlinks=True))
    with open(copy / "results/campaign/summary.csv") as f:
        built = list(csv.DictReader(f))
    (copy / "config/mine").mkdir()
    (copy / "config/mine/broken.csv").write_text("t,x,y\n0,0,zero\n")
    good = ["../" + line for line in (copy / "config/campaign.csv").read_text().splitlines()[1:3]]
    rows = [*good, "broken.csv,0.005,0.4,33,,felt,steel,,,,", "gone.csv,0.005,0.4,33,,felt,,,,,"]
    header = (copy / "config/campaign.csv").read_text().splitlines()[0]
    assert header.split(",")[5] == "surface"  # a table without it: grouped by ball
    lines = [",".join(v for i, v in enumerate(r.split(",")) if i != 5) for r in [header, *rows]]
    (copy / "config/mine/table.csv").write_text("\n".join(lines) + "\n")
    config = copy / "config/config.yaml"
    config.write_text(config.read_text() + "campaign: {table: config/mine/table.csv}\n")
    proc = ci_build.snakemake(copy, "--cores", "2", "campaign")
    assert proc.returncode == 0, proc.stderr[-3000:]
    with open(copy / "results/campaign/summary.csv") as f:
        summary = {r["row"]: r for r in csv.DictReader(f)}
    assert [summary[r]["status"] for r in "2345"] == ["fitted", "fitted", "failed", "failed"]
    assert [summary[r]["value"] for r in "23"] == [r["value"] for r in built[:2]]
    assert "broken.csv" in summary["4"]["warnings"]
    assert "not found" in summary["5"]["warnings"]
    out = subprocess.run(
        [sys.executable, str(ci_build.ROOT / "tools/build_summary.py")],
        cwd=copy, capture_output=True, text=True, check=True,
    ).stdout  # fmt: skip
    assert "campaign: 2 films fitted, 2 failed" in out
    assert "failed: row 4 (config/mine/broken.csv): turntable fit: " in out
    assert "failed: row 5 (config/mine/gone.csv): file config/mine/gone.csv not found" in out


def test_the_campaign_in_the_build(clean_build):
    with open(clean_build / "results/campaign/summary.csv") as f:
        rows = list(csv.DictReader(f))
    assert rows
    assert all(r["film"].startswith("SYNTHETIC") for r in rows)
    assert {Path(r["file"]).suffix for r in rows} == {".csv", ".mp4"}
    for r in rows:
        assert r["selected"] == r["true_model"], r
        error = abs(float(r["value"]) - float(r["true_value"]))
        # a tracked video too: its errors drift, and its standard error allows for that
        assert error < 4 * float(r["stderr"]), r
        assert error < 0.05 * float(r["true_value"]), r
    log = (clean_build / "logs/campaign/summary.log").read_text()
    assert log.startswith(f"{len(rows)} films fitted, 0 failed\n")
