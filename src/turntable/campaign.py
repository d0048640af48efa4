"""A campaign of films: a table with one film per row, each fitted by ``turntable fit``.

The table is a CSV file with the columns ``file`` (a tracked film, relative to the table's
folder), ``radius_m``, ``k``, ``rpm`` (empty if unknown) and ``platter_radius_m`` (for
videos); every other column is a free label (surface, ball, ...). A row whose file lies
under ``results/`` and whose label ``true_model`` is set is a SYNTHETIC film, which the
workflow writes itself from the labels ``true_model``, ``true_value`` and ``seed``. A bad
row is reported with its number and what is wrong, and the other films are fitted all the
same.

``python -m turntable.campaign fit ARGS_JSON OUT.json`` fits a batch of films (``{name:
Film.fit_options()}``) in one process and writes ``{name: the result of turntable fit, or the
one line that refused the film}``;
``python -m turntable.campaign simulate SPEC_JSON OUT [TRUTH.csv]`` writes a synthetic film
or video.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from turntable._atomic import write_text
from turntable._progress import Progress

COLUMNS = ("file", "radius_m", "k", "rpm", "platter_radius_m")
COEFFICIENT = {"slipping": "mu0", "rolling_resistance": "delta"}
SUMMARY_COLUMNS = [
    "film", "row", "file", "status", "selected", "coefficient", "value", "stderr",
    "decisive", "warnings",
]  # fmt: skip


class CampaignError(ValueError):
    """The table cannot be read at all (missing, or without the required columns)."""


@dataclass(frozen=True)
class Film:
    """One row of the table: the film ``name`` (its file's stem) at ``path``."""

    row: int
    name: str
    path: str
    radius_m: float
    k: float
    rpm: float | None
    platter_radius_m: float | None
    labels: dict[str, str] = field(default_factory=dict)
    synthetic: bool = False

    def fit_options(self) -> dict[str, Any]:
        """The arguments of `turntable.fitting.fit_file` for this film (JSON)."""
        return {
            "path": self.path,
            "radius": self.radius_m,
            "k": self.k,
            "rpm": self.rpm,
            "platter_radius": self.platter_radius_m,
        }


def _number(text: str, name: str, optional: bool = False) -> float | None:
    if optional and not text.strip():
        return None
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{name} {text.strip()!r} is not a number") from None
    if not (math.isfinite(value) and value > 0):
        raise ValueError(f"{name} {text.strip()!r} is not a positive number")
    return value


def _check_synthetic(film: Film) -> None:
    if not film.name.startswith("SYNTHETIC"):
        raise ValueError(f"a synthetic film's name must start with SYNTHETIC, not {film.name!r}")
    if film.labels["true_model"] not in COEFFICIENT:
        raise ValueError(f"true_model must be one of {', '.join(COEFFICIENT)}")
    _number(film.labels.get("true_value", ""), "true_value")
    if not film.labels.get("seed", "").isdigit():
        raise ValueError("seed must be a whole number >= 0")
    if film.rpm is None:
        raise ValueError("rpm is empty")


def read_table(
    path: str | os.PathLike[str], results: str = "results", group_by: str | None = None
) -> tuple[list[Film], list[dict[str, Any]]]:
    """The films of the table at `path`, and its bad rows.

    A row is bad if a number is missing or not positive, its file is not found (and is not
    a synthetic film, under `results`), or its name is that of an earlier row. A table
    without the columns `COLUMNS` and `group_by` is refused (`CampaignError`).
    Each bad row is ``{"row": n, "file": ..., "error": one line}``; ``n`` counts the header
    as row 1, as a spreadsheet does.
    """
    table = Path(path)
    try:
        text = table.read_text(encoding="utf-8-sig")
    except OSError as exc:
        raise CampaignError(f"campaign table {table}: {exc.strerror}") from None
    reader = csv.DictReader(io.StringIO(text))
    missing = [c for c in COLUMNS if c not in (reader.fieldnames or [])]
    missing += [group_by] if group_by and group_by not in (reader.fieldnames or []) else []
    if missing:
        raise CampaignError(f"campaign table {table}: no column {', '.join(missing)}")
    films: list[Film] = []
    bad: list[dict[str, Any]] = []
    names: set[str] = set()
    for row, record in enumerate(reader, start=2):
        file = (record["file"] or "").strip()
        film_path = os.path.normpath(table.parent / file)
        try:
            if not file:
                raise ValueError("file is empty")
            synthetic = bool(record.get("true_model")) and Path(film_path).is_relative_to(results)
            if not (synthetic or Path(film_path).is_file()):
                raise ValueError(f"file {film_path} not found")
            platter = _number(record["platter_radius_m"] or "", "platter_radius_m", True)
            rpm = _number(record["rpm"] or "", "rpm", optional=platter is not None)
            film = Film(
                row, Path(file).stem, film_path,
                _number(record["radius_m"] or "", "radius_m"), _number(record["k"] or "", "k"),
                rpm, platter,
                {k: (v or "").strip() for k, v in record.items() if k not in COLUMNS and k},
                synthetic,
            )  # fmt: skip
            if synthetic:
                _check_synthetic(film)
            if film.name in names:
                raise ValueError(f"film name {film.name!r} is that of an earlier row")
        except ValueError as exc:
            bad.append({"row": row, "file": film_path if file else "", "error": str(exc)})
            continue
        names.add(film.name)
        films.append(film)
    return films, bad


def fit_film(options: dict[str, Any]) -> dict[str, Any]:
    """The result of ``turntable fit`` (`turntable.fitting.fit_file`) for the film of
    `Film.fit_options`, or ``{"error": the line that refused the film}``."""
    from turntable.fitting import InputError, fit_file

    try:
        return fit_file(**options)
    except InputError as exc:
        return {"error": f"turntable fit: error: {exc}"}


def batches(names: list[str], size: int) -> dict[str, list[str]]:
    """The films `names`, in the table's order, in batches of `size`: ``{"1": [...], ...}``.

    >>> batches(["a", "b", "c"], 2)
    {'1': ['a', 'b'], '2': ['c']}
    """
    return {str(i // size + 1): names[i : i + size] for i in range(0, len(names), size)}


def group_column(films: list[Film], group_by: str) -> str:
    """The label that groups the films in the figure: `group_by` if set, else the table's
    first label column, else none (``""``)."""
    if group_by or not films:
        return group_by
    return next(iter(films[0].labels), "")


def summary_row(film: dict[str, Any], result: dict[str, Any]) -> dict[str, Any]:
    """One row of the summary: the selected model's coefficient, or why there is none."""
    row = {"film": film["name"], "row": film["row"], "file": film["path"], **film["labels"]}
    if "error" in result:
        return row | {"status": "failed", "warnings": result["error"]}
    selected = result["selected"]
    shown = selected or min(COEFFICIENT, key=lambda m: result[m]["aicc"])
    name = COEFFICIENT[shown]
    return row | {
        "status": "fitted",
        "selected": selected or "",
        "coefficient": name,
        "value": result[shown][name],
        "stderr": result[shown][f"{name}_stderr"],
        "decisive": result["selection"]["decisive"],
        "warnings": " | ".join(result["warnings"]),
    }


def write_summary(path: str | os.PathLike[str], rows: list[dict[str, Any]]) -> None:
    """The summary CSV: `SUMMARY_COLUMNS`, then the labels of the table."""
    labels = list(dict.fromkeys(k for r in rows for k in r if k not in SUMMARY_COLUMNS))
    with open(path, "w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, [*SUMMARY_COLUMNS, *labels], lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


def simulation(
    film: Film, section: dict[str, Any], video: dict[str, Any] | None = None
) -> dict[str, Any]:
    """What `simulate` needs of a synthetic `film`: section ``film`` of the configuration
    (camera and start) with the row's ball and turntable, and the row's truth; for a video,
    also the scene of section `video` (``fig10_video``) with the row's platter."""
    ball = {"radius_m": film.radius_m, "k": film.k, "rpm": film.rpm}
    labels = film.labels
    spec = {
        "film": dict(section) | ball,
        "model": labels["true_model"],
        "value": float(labels["true_value"]),
        "seed": int(labels["seed"]),
    }
    if film.platter_radius_m is not None and video is not None:
        spec["scene"] = {
            "platter_radius": film.platter_radius_m,
            "tilt_deg": video["tilt_deg"],
            "roll_deg": video["roll_deg"],
            "size": list(video["size"]),
            "fps": video["fps"],
            "duration": video["duration_s"],
            "noise": video["noise"],
        }
    return spec


def simulate(
    spec: dict[str, Any],
    path: str | os.PathLike[str],
    truth: str | os.PathLike[str] = "",
    progress: Progress | None = None,
) -> None:
    """Write the SYNTHETIC film of `spec` (`simulation`) to `path`: a tracked film (CSV),
    or a video (`turntable.video.render`, which calls `progress`) when `spec` has a scene,
    with the true positions of its frames at `truth` if given."""
    from turntable import film, fit, solution

    rig = film.rig_from_config(spec["film"])
    z0 = rig.state0
    if spec["model"] == "rolling_resistance":
        z0 = solution.no_slip_state(z0, rig.setup.k)
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    if "scene" not in spec:
        args = (spec["model"], spec["value"], z0, rig.setup, rig.camera, spec["seed"])
        film.write_film(path, fit.simulate_film(*args), fit.synthetic_header(*args))
        return
    from turntable.video.render import Scene, render_video

    scene = Scene(**(spec["scene"] | {"size": tuple(spec["scene"]["size"])}))
    setup = rig.setup._replace(axis=(0.0, 0.0))
    rendered = render_video(
        path, spec["model"], spec["value"], z0, setup, scene, spec["seed"], progress=progress
    )
    if truth:
        head = "SYNTHETIC DATA: the true positions of the ball of the rendered video"
        truth_of = f"truth: model = {spec['model']}, coefficient = {spec['value']!r}"
        film.write_film(truth, rendered.film, [head, truth_of])


def _write_json(record: dict[str, Any], out: str) -> None:
    write_text(out, json.dumps(record, indent=1, allow_nan=False))


def main(argv: list[str] | None = None) -> int:
    command, spec, *out = sys.argv[1:] if argv is None else argv
    if command == "simulate":
        from turntable._terminal import bars

        with bars() as progress:
            simulate(json.loads(spec), *out, progress=progress)
    else:
        _write_json({name: fit_film(options) for name, options in json.loads(spec).items()}, *out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
