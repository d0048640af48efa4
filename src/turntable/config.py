"""Checks of a configuration of the workflow, run before it plans any job.

`validate` checks a configuration against its JSON schema
(``workflow/schemas/config.schema.yaml``: types, bounds, defaults) and fills in the
defaults; `problems` checks what a schema cannot say: spans are increasing, a span ends
where the solution is representable in doubles and a figure can still show it, a film has
enough frames, names of films differ, the animated ball stays in its panels.
"""

from __future__ import annotations

import copy
import math
import sys
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np
import yaml
from jsonschema import Draft202012Validator, validators
from referencing import Registry, Resource
from referencing.jsonschema import DRAFT202012

from turntable import rolling
from turntable.film import rig_from_config
from turntable.solution import max_time, no_slip_state, nonholonomic, solve
from turntable.spectrum import alpha1_peak, spectrum

#: A drawn span has at least this many sample points per turn of the spiral.
MIN_POINTS_PER_TURN = 30
#: A drawn motion grows by at most this factor over its span.
MAX_GROWTH = 1.0e6
#: Frames of a film: enough for the larger model of ``turntable fit`` (7 parameters), and
#: not so many that a fit exhausts the memory.
MIN_FRAMES, MAX_FRAMES = 16, 10**6

#: The spans of the exact solution: section, span key, mu0 key, state key, and how it is
#: drawn (n_points key, "growth" for a log time axis, None for a span not drawn).
SPANS = [
    ("fig3_modal_terms", "t_span", "mu0", "state", "n_points"),
    ("fig4_trajectories", "t_span", "mu0", "state", "n_points"),
    ("fig6_limit", "layer_t_span", "mu0_layer", "layer_state", "growth"),
    ("fig7_rolling_resistance", "t_span", "mu0", "state", "n_points"),
    ("study", "t_span", "mu0_range", "state", None),
    ("animation", "t_end", "mu0", "state", None),
]


def _fill(validator: Any, props: Mapping, instance: Any, schema: Mapping) -> Iterator[Any]:
    """JSON Schema's ``properties``, filling in the defaults of missing keys first."""
    for key, sub in props.items():
        if isinstance(instance, dict) and "default" in sub:
            instance.setdefault(key, copy.deepcopy(sub["default"]))
    yield from Draft202012Validator.VALIDATORS["properties"](validator, props, instance, schema)


def _load(uri: str) -> Resource:
    """A schema file, read in the dialect of every schema here (draft 2020-12)."""
    schema = yaml.safe_load(Path(uri.removeprefix("file://")).read_text(encoding="utf-8"))
    schema.pop("$schema", None)
    return Resource.from_contents(schema, default_specification=DRAFT202012)


#: Draft 2020-12 filling in defaults, where an integer is an int (not 400.0) and a number
#: is finite.
Validator = validators.extend(
    Draft202012Validator,
    {"properties": _fill},
    type_checker=Draft202012Validator.TYPE_CHECKER.redefine_many(
        {
            "integer": lambda _, v: type(v) is int,
            "number": lambda _, v: type(v) in (int, float) and math.isfinite(v),
        }
    ),
)


def validate(config: dict[str, Any], schema: str | Path) -> list[str]:
    """Fill in the defaults of `config` from `schema` and return one line per problem.

    Each line is the key's path (``section.key[i]``) and what is expected.
    """
    uri = Path(schema).resolve().as_uri()
    validator = Validator(_load(uri).contents | {"$id": uri}, registry=Registry(retrieve=_load))
    lines = []
    for error in sorted(validator.iter_errors(config), key=lambda e: list(map(str, e.path))):
        at = "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in error.absolute_path)
        text = isinstance(error.instance, str) and error.validator == "type"
        hint = (
            " (YAML reads it as text: write 1.0e-4)" if text and _is_float(error.instance) else ""
        )
        lines.append(f"{at[1:] or 'configuration'}: {error.message}{hint}")
    return lines


def _is_float(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def problems(config: Mapping[str, Any]) -> list[str]:
    """Return one line per problem of a configuration that passed its schema.

    Each line names the key (``section.key`` or ``section.key[i]``) and what is expected.
    """
    found = list(_order(config))
    if found:
        return found
    found += _film(config)
    for spec in SPANS:
        found += _spans(config, *spec)
    return found + _animation(config)


def _order(config: Mapping[str, Any]) -> Iterator[str]:
    """Pairs named ``*_span`` or ``*_range`` increase; names of films differ."""
    for section, values in config.items():
        for key, value in values.items():
            if not key.endswith(("_span", "_range")):
                continue
            nested = isinstance(value[0], list)
            for i, pair in enumerate(value if nested else [value]):
                if not pair[0] < pair[1]:
                    at = f"{section}.{key}" + (f"[{i}]" if nested else "")
                    yield f"{at} = {pair}: expected [start, end] with start < end"
    names = [film["name"] for film in config["synthetic_film"]["films"]]
    for i, name in enumerate(names):
        if name in names[:i]:
            yield f"synthetic_film.films[{i}].name = {name!r}: expected a name of its own"


def _mu0_samples(low: float, high: float, k: float) -> np.ndarray:
    """A log grid of [low, high], 32 per decade, with the peak of alpha1."""
    grid = np.geomspace(low, high, max(2, math.ceil(32 * math.log10(high / low)) + 1))
    peak = float(alpha1_peak(k).mu0)
    return np.append(grid, [peak] if low < peak < high else [])


def _late(end: float, mu0s: list[float], k: float, z0: Any) -> str | None:
    """Why the solution from z0 is not representable at `end` for one of mu0s, or None."""
    bound = max_time(np.asarray(mu0s), k)
    worst_first = np.asarray(mu0s)[np.argsort(bound)]
    for mu0 in worst_first[2.0 * end > np.sort(bound)]:  # a state moves the bound < half
        limit = float(max_time(mu0, k, z0))
        if end > limit:
            return (
                f"ends at t = {end:g}, after t = {limit:.6g}, where the solution for "
                f"mu0 = {mu0:.6g}, k = {k:g} leaves the doubles; expected t <= {limit:.6g}"
            )
    return None


def _spans(
    config: Mapping[str, Any],
    section: str,
    key: str,
    mu0_key: str,
    state_key: str,
    drawn: str | None,
) -> list[str]:
    """The span `section.key` ends where the solution is representable and, if drawn,
    where the figure still shows it: a growth of at most MAX_GROWTH, and enough points."""
    s = config[section]
    mu0s = list(s[mu0_key]) if isinstance(s[mu0_key], list) else [s[mu0_key]]
    value = s[key]
    if isinstance(value, list) and isinstance(value[0], list):  # one span per mu0
        if len(value) != len(mu0s):
            return [
                f"{section}.{key} has {len(value)} spans for {len(mu0s)} values of "
                f"{section}.{mu0_key}: expected one span each"
            ]
        cases = [
            (f"{section}.{key}[{i}]", span, [m])
            for i, (span, m) in enumerate(zip(value, mu0s, strict=True))
        ]
    else:
        span = value if isinstance(value, list) else [0.0, value]
        cases = [(f"{section}.{key}", span, mu0s)]
    found = []
    for k in s["k"] if isinstance(s["k"], list) else [s["k"]]:
        comparison = s.get("comparison")
        z0 = no_slip_state(s[state_key], k) if comparison else s[state_key]
        for at, (t0, t1), ms in cases:
            ms = list(_mu0_samples(*ms, k)) if mu0_key.endswith("_range") else ms
            why = _late(t1, ms, k, z0)
            # (growth rate, fastest angular frequency) of each motion drawn
            motions = [(float(spectrum(m, k).alpha1), float(spectrum(m, k).beta)) for m in ms]
            for m in ms if comparison and not why else []:
                delta = float(rolling.matched_delta(m, k, comparison))
                try:
                    rolling.solve(z0, [t1], delta, k)
                except ValueError as exc:
                    why = f"ends at t = {t1:g}, too late for the rolling ball: {exc}"
                r = rolling.spectrum(delta, k)
                motions.append((float(r.sigma_g), max(abs(float(r.nu_g)), abs(float(r.nu_c)))))
            if why:
                found.append(f"{at} {why}")
                continue
            if drawn is None:
                continue
            rate = max(rate for rate, _ in motions)
            if rate * t1 > math.log(MAX_GROWTH):
                found.append(
                    f"{at} = [{t0:g}, {t1:g}]: the motion grows by e^({rate:.3g} t), "
                    f"more than {MAX_GROWTH:.0e} by the end; expected t_end <= "
                    f"{math.log(MAX_GROWTH) / rate:.4g}"
                )
            turns = max(f for _, f in motions) * (t1 - t0) / (2 * math.pi)
            if drawn != "growth" and s[drawn] - 1 < MIN_POINTS_PER_TURN * turns:
                need = math.ceil(MIN_POINTS_PER_TURN * turns) + 1
                found.append(
                    f"{at} = [{t0:g}, {t1:g}] holds {turns:.4g} turns of the spiral, "
                    f"drawn with {section}.{drawn} = {s[drawn]} points; expected at "
                    f"least {MIN_POINTS_PER_TURN} points per turn: {drawn} >= {need} "
                    "or a shorter span"
                )
    return found


def _film(config: Mapping[str, Any]) -> list[str]:
    """The film has from MIN_FRAMES to MAX_FRAMES frames, and every motion it is compared
    with (the synthetic films, Fig. 8's range) is representable until its end."""
    f = config["film"]
    n = math.floor(f["duration_s"] * f["fps"] * (1.0 + 1e-12)) + 1
    if not MIN_FRAMES <= n <= MAX_FRAMES:
        return [
            f"film.duration_s = {f['duration_s']:g} s at film.fps = {f['fps']:g} gives "
            f"{n} frames; expected from {MIN_FRAMES} to {MAX_FRAMES} frames"
        ]
    try:
        rig = rig_from_config(f)
    except ValueError as exc:
        return [f"film: {exc}"]
    k, end = rig.setup.k, rig.setup.omega * (n - 1) / f["fps"]
    low, high = config["fig8_measurability"]["mu0_range"]
    cases = [(film["model"], [film["coefficient"]]) for film in config["synthetic_film"]["films"]]
    grid = np.geomspace(low, high, max(2, math.ceil(32 * math.log10(high / low)) + 1))
    late = grid[np.asarray(rolling.growth_rate(grid, k)) * end > 0.5 * math.log(sys.float_info.max)]
    cases += [("slipping", list(_mu0_samples(low, high, k))), ("rolling_resistance", list(late))]
    for model, coefficients in cases:
        if model == "slipping":
            why = _late(end, coefficients, k, rig.state0)
        else:
            why = None
            for delta in coefficients:
                try:
                    rolling.solve(no_slip_state(rig.state0, k), [end], delta, k)
                except ValueError as exc:
                    why = f"ends too late for the rolling ball (delta = {delta:.6g}): {exc}"
                    break
        if why:
            return [f"film.duration_s = {f['duration_s']:g} s (t Omega = {end:.6g}) {why}"]
    return []


def _animation(config: Mapping[str, Any]) -> list[str]:
    """Both balls of the animation stay within its panels: at most size/2 - 1.5 R from the
    axis, so that the ball is drawn at least two pixels wide."""
    a = config["animation"]
    t = np.linspace(0.0, a["t_end"], (a["n_frames"] - 1) * a["substeps"] + 1)
    paths = [solve(a["state"], t, a["mu0"], a["k"]), nonholonomic(a["state"], t, a["k"])]
    reach = max(float(np.max(np.hypot(z[:, 0], z[:, 1]))) for z in paths)
    if reach + 1.5 <= a["size"] / 2:
        return []
    return [
        f"animation.t_end = {a['t_end']:g}: the ball goes {reach:.4g} R from the axis; "
        f"expected at most animation.size / 2 - 1.5 = {a['size'] / 2 - 1.5:g} R"
    ]
