"""Checks of a configuration of the workflow, run before it plans any job: `validate`
against its JSON schema (``workflow/schemas/config.schema.yaml``), filling in the defaults,
and `problems`, what a schema cannot say (spans the model or a figure cannot show, films)."""

from __future__ import annotations

import copy
import functools
import math
import re
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
from turntable._json import validator_class
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
#: A number that YAML reads as text: an exponent without a dot or a sign (1e-4, 1e5).
NUMBER = r"[-+]?\d+(\.\d*)?[eE][-+]?\d+"

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
Validator = validators.extend(validator_class(finite_numbers=True), {"properties": _fill})


@functools.cache
def _validator(uri: str) -> Any:
    return Validator(_load(uri).contents | {"$id": uri}, registry=Registry(retrieve=_load))


def validate(config: dict[str, Any], schema: str | Path) -> list[str]:
    """Fill in the defaults of ``config`` from ``schema`` and return one line per problem.

    Each line is the key's path (``section.key[i]``) and what is expected.

    Parameters
    ----------
    config : dict
        The configuration (sections of ``config/config.yaml``); filled in place.
    schema : str or pathlib.Path
        Path of the JSON Schema (``workflow/schemas/config.schema.yaml``).

    Returns
    -------
    list of str
        One line per problem; empty when the configuration is valid.

    Examples
    --------
    From the repository's root:

    >>> from turntable.config import validate
    >>> schema = "workflow/schemas/config.schema.yaml"
    >>> validate({"fig2_spectrum": {"n_points": 400.0}}, schema)
    ["fig2_spectrum.n_points: 400.0 is not of type 'integer'"]
    >>> config = {}
    >>> validate(config, schema), config["fig3_modal_terms"]["t_span"]
    ([], [0.0, 40.0])
    """
    lines = []
    for error in sorted(
        _validator(Path(schema).resolve().as_uri()).iter_errors(config),
        key=lambda e: list(map(str, e.path)),
    ):
        at = "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in error.absolute_path)
        text = isinstance(error.instance, str) and re.fullmatch(NUMBER, error.instance)
        hint = " (YAML reads it as text: write 1.0e-4)" if text else ""
        lines.append(f"{at[1:] or 'configuration'}: {error.message}{hint}")
    return lines


def problems(config: Mapping[str, Any]) -> list[str]:
    """Return one line per problem of a configuration that passed `validate`: the key
    (``section.key[i]``) and what is expected.

    Parameters
    ----------
    config : mapping
        A configuration that passed `validate` (its defaults filled in).

    Returns
    -------
    list of str
        One line per problem; empty when there is none.

    Examples
    --------
    >>> from turntable.config import problems, validate
    >>> config = {"fig3_modal_terms": {"t_span": [5.0, 1.0]}}
    >>> validate(config, "workflow/schemas/config.schema.yaml")
    []
    >>> problems(config)
    ['fig3_modal_terms.t_span = [5.0, 1.0]: expected [start, end] with start < end']
    """
    found = list(_order(config))
    if not found:
        found = _film(config) + [p for spec in SPANS for p in _spans(config, *spec)]
        found += _animation(config)
    return found


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


def _grid(low: float, high: float, k: float) -> list[float]:
    """[low, high], 32 values per decade and the peak of alpha1 (the fastest growth)."""
    grid = np.geomspace(low, high, max(2, math.ceil(32 * math.log10(high / low)) + 1))
    peak = float(alpha1_peak(k).mu0)
    return [*map(float, grid), *([peak] if low < peak < high else [])]


def _late(end: float, model: str, coefficients: list[float], k: float, z0: Any) -> str | None:
    """Why the ball of `model` from z0 leaves the doubles by `end` for one of the
    coefficients (mu0 or delta), or None. Those whose growth alone reaches half the range of
    the doubles are tried, fastest first: a state moves the bound by far less."""
    if not coefficients:
        return None
    c = np.asarray(coefficients, dtype=float)
    slipping = model == "slipping"
    rate = np.asarray(spectrum(c, k).alpha1 if slipping else rolling.growth_rate(c, k))
    order = np.argsort(-rate)
    for x in c[order][rate[order] * end > 0.5 * math.log(sys.float_info.max)]:
        if slipping:
            limit = float(max_time(x, k, z0))
            if end > limit:
                return (
                    f"ends at t = {end:g}, after t = {limit:.6g}, where the slipping ball "
                    f"(mu0 = {x:.6g}, k = {k:g}) leaves the doubles; expected t <= {limit:.6g}"
                )
            continue
        try:
            rolling.solve(z0, [end], x, k)
        except ValueError as exc:
            return f"ends at t = {end:g}, too late for the rolling ball (delta = {x:.6g}): {exc}"
    return None


def _spans(
    config: Mapping[str, Any], section: str, key: str, mu0_key: str, state: str, drawn: str | None
) -> list[str]:
    """The span `section.key` ends where the solution is representable and, if `drawn`,
    where the figure shows it: a growth of at most MAX_GROWTH, and enough points per turn."""
    s = config[section]
    mu0s = s[mu0_key] if isinstance(s[mu0_key], list) else [s[mu0_key]]
    value = s[key] if isinstance(s[key], list) else [0.0, s[key]]
    if isinstance(value[0], list):  # one span per mu0
        if len(value) != len(mu0s):
            n = f"{len(value)} spans for {len(mu0s)} values of {section}.{mu0_key}"
            return [f"{section}.{key} has {n}: expected one span each"]
        cases = [
            (f"{section}.{key}[{i}]", v, [m])
            for i, (v, m) in enumerate(zip(value, mu0s, strict=True))
        ]
    else:
        cases = [(f"{section}.{key}", value, mu0s)]
    comparison, found = s.get("comparison"), []
    for k in s["k"] if isinstance(s["k"], list) else [s["k"]]:
        z0 = no_slip_state(s[state], k) if comparison else s[state]
        for at, (t0, t1), ms in cases:
            ms = _grid(*ms, k) if mu0_key.endswith("_range") else ms
            ds = [float(rolling.matched_delta(m, k, comparison)) for m in ms if comparison]
            why = _late(t1, "slipping", ms, k, z0) or _late(t1, "rolling_resistance", ds, k, z0)
            if why or not drawn:
                found += [f"{at} {why}"] if why else []
                continue
            # growth rates and fastest angular frequencies of the motions drawn
            sp, r = [spectrum(m, k) for m in ms], [rolling.spectrum(d, k) for d in ds]
            rate = max([float(x.alpha1) for x in sp] + [float(x.sigma_g) for x in r])
            freqs = [float(x.beta) for x in sp] + [
                abs(float(f)) for x in r for f in (x.nu_g, x.nu_c)
            ]
            turns = max(freqs) * (t1 - t0) / (2 * math.pi)
            if rate * t1 > math.log(MAX_GROWTH):
                found.append(
                    f"{at} = [{t0:g}, {t1:g}]: the motion grows by e^({rate:.3g} t), more "
                    f"than {MAX_GROWTH:.0e} by the end; expected t_end <= "
                    f"{math.log(MAX_GROWTH) / rate:.4g}"
                )
            if drawn != "growth" and s[drawn] - 1 < MIN_POINTS_PER_TURN * turns:
                found.append(
                    f"{at} = [{t0:g}, {t1:g}] holds {turns:.4g} turns, drawn with "
                    f"{section}.{drawn} = {s[drawn]} points; expected at least "
                    f"{MIN_POINTS_PER_TURN} per turn: "
                    f"{drawn} >= {math.ceil(MIN_POINTS_PER_TURN * turns) + 1} or a shorter span"
                )
    return found


def _film(config: Mapping[str, Any]) -> list[str]:
    """The film has from MIN_FRAMES to MAX_FRAMES frames, and the motions it is compared
    with (the synthetic films, Fig. 8's range) stay representable until its end."""
    f = config["film"]
    n = math.floor(f["duration_s"] * f["fps"] * (1.0 + 1e-12)) + 1
    given = f"film.duration_s = {f['duration_s']:g} s at film.fps = {f['fps']:g}"
    if not MIN_FRAMES <= n <= MAX_FRAMES:
        return [f"{given} gives {n} frames; expected from {MIN_FRAMES} to {MAX_FRAMES} frames"]
    try:
        rig = rig_from_config(f)
    except ValueError as exc:
        return [f"film: {exc}"]
    k, end = rig.setup.k, rig.setup.omega * (n - 1) / f["fps"]
    grid = _grid(*config["fig8_measurability"]["mu0_range"], k)
    for model in ("slipping", "rolling_resistance"):
        z0 = rig.state0 if model == "slipping" else no_slip_state(rig.state0, k)
        cs = [
            film["coefficient"]
            for film in config["synthetic_film"]["films"]
            if film["model"] == model
        ]
        if why := _late(end, model, cs + grid, k, z0):
            return [f"{given} (t Omega = {end:.6g}) {why}"]
    return []


def _animation(config: Mapping[str, Any]) -> list[str]:
    """Both balls of the animation stay at most size/2 - 1.5 R from the axis, so that they
    are drawn at least two pixels wide."""
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
