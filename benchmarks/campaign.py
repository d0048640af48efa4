"""Scale of a campaign: N tracked films fitted by the workflow on this machine.

Writes N SYNTHETIC films (2,400 frames each by default: the camera of section ``film``,
240 frames/s for 10 s; models, coefficients and rates drawn at random over the range
Figure 8 says a film can measure) and their table into a temporary copy of the workflow's
sources, then times ``snakemake campaign --cores N`` there: one job per batch of films
(``--batch-size``, the configuration's ``campaign.batch_size``), and the gathering job.
Records the wall time, the time per film, the CPU time and the load.

Run ``python benchmarks/campaign.py [--films 1000] [--cores 2] [--batch-size 50]``; the
result is merged into ``results/benchmarks.json`` under the key ``campaign``.
"""

from __future__ import annotations

import argparse
import csv
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from results_file import ROOT, merge_results
from turntable.campaign import Film, simulate, simulation
from turntable.config import validate

SOURCES = ["config", "workflow", "scripts", "paper", "src", "profiles"]


def write_films(folder: Path, n: int, seed: int) -> Path:
    """`n` SYNTHETIC films in `folder` and their table; returns the table's path."""
    section = {}
    validate(section, ROOT / "workflow/schemas/config.schema.yaml")
    folder.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(seed)
    rows = []
    for i in range(n):
        model = ("slipping", "rolling_resistance")[i % 2]
        value = 10 ** rng.uniform(-0.5, 1.0) if model == "slipping" else 10 ** rng.uniform(-3, -1.5)
        rpm = float(rng.choice([33.333333333333336, 45.0]))
        name = f"SYNTHETIC_{i:04d}.csv"
        labels = {"surface": f"s{i % 5}", "true_model": model, "true_value": repr(value)}
        film = Film(
            i + 2, name, str(folder / name), 0.005, 0.4, rpm, None, labels | {"seed": str(i)}, True
        )
        simulate(simulation(film, section["film"]), film.path)
        rows.append(
            {"file": name, "radius_m": 0.005, "k": 0.4, "rpm": rpm, "platter_radius_m": ""} | labels
        )
    table = folder / "table.csv"
    with table.open("w", newline="") as f:
        writer = csv.DictWriter(f, list(rows[0]), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    return table


def run(films: int, cores: int, seed: int = 0, batch_size: int = 50) -> dict[str, Any]:
    """Write `films` SYNTHETIC films and time ``snakemake campaign`` on them."""
    with tempfile.TemporaryDirectory(prefix="turntable-campaign-") as tmp:
        work = Path(tmp)
        for name in SOURCES:
            shutil.copytree(ROOT / name, work / name, ignore=shutil.ignore_patterns("__pycache__"))
        start = time.perf_counter()
        table = write_films(work / "films", films, seed)
        written = time.perf_counter() - start
        (work / "config/config.yaml").write_text(
            f"campaign: {{table: {table}, batch_size: {batch_size}}}\n"
        )
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        snakemake = str(Path(sys.executable).with_name("snakemake"))
        subprocess.run(
            [snakemake, "campaign", "--cores", str(cores), "-q"],
            cwd=work,
            env=os.environ | {"PYTHONPATH": str(work / "src")},
            check=True,
        )
        wall = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        with (work / "results/campaign/summary.csv").open() as f:
            summary = list(csv.DictReader(f))
    cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
    right = sum(r["selected"] == r["true_model"] for r in summary)
    return {
        "command": f"python benchmarks/campaign.py --films {films} --cores {cores} "
        f"--batch-size {batch_size}",
        "films": films,
        "frames_per_film": 2400,
        "cores": cores,
        "batch_size": batch_size,
        "write_films_s": round(written, 1),
        "snakemake_campaign_s": round(wall, 1),
        "per_film_s": round(wall / films, 3),
        "cpu_s": round(cpu, 1),
        "cpu_per_film_s": round(cpu / films, 3),
        "fitted": sum(r["status"] == "fitted" for r in summary),
        "selected_the_true_model": right,
        "load_average_1min_at_end": round(os.getloadavg()[0], 2),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.partition("\n")[0])
    parser.add_argument("--films", type=int, default=1000)
    parser.add_argument("--cores", type=int, default=os.cpu_count())
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--batch-size", type=int, default=50)
    args = parser.parse_args()
    result = run(args.films, args.cores, args.seed, args.batch_size)
    merge_results(ROOT / "results/benchmarks.json", {"campaign": result})
    print(result)


if __name__ == "__main__":
    main()
