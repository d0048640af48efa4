"""Checks of the workflow configuration, run by the Snakefile before any job.

A mistake in config/config.yaml (or in a file given with ``--configfile``) stops Snakemake
before it plans or runs a job, so that nothing already built is deleted or overwritten. The
message has one line per problem (at most `MAX_PROBLEMS`), each naming the file and line,
the key, the value and what is expected. The checks are driven by the JSON schema
workflow/schemas/config.schema.yaml and by naming conventions, not by a list of keys:

- every value has the type and the bounds the schema gives; an integer must be an int
  (JSON Schema counts 400.0 as an integer), a number must be finite, and a number that YAML
  read as text (``1e-4``: YAML wants a dot and a signed exponent) is told how to write it;
- a missing key is told with its description and default, an unknown key with the key it
  probably misspells; a key given twice in one file (YAML keeps the last silently) is told;
- a key whose name ends in ``_span`` or ``_range`` is an increasing [start, end] pair, or
  a list of such pairs;
- in a list of entries with a ``name`` (which names their files), the names differ;
- a key with the schema annotation ``x-solution-times`` (described in the schema) ends at a
  time at which the solution is representable in doubles, as `turntable.max_time` tells
  (and `turntable.rolling.solve` for the rolling ball); a list of spans has one span per
  friction coefficient;
- a span that a figure draws (schema annotation ``x-drawn``) keeps the motion readable: it
  grows at most `MAX_GROWTH` over the span, and, sampled at ``n_points`` evenly spaced times,
  has at least `MIN_POINTS_PER_TURN` points per turn of the spiral (`drawing_problems`);
- the ``claims`` section is checked against the package's schema of the claims parameters
  (src/turntable/claims/params.schema.yaml, which `turntable.claims.resolve_params` uses
  too); importing `turntable.claims` itself would cost every Snakemake run 1.5 s;
- the film of section ``film`` has enough frames for the fits of ``turntable fit`` and
  Fig. 8 (`MIN_FRAMES`), not so many that they exhaust the memory (`MAX_FRAMES`), and ends
  where the synthetic films and the motions of Fig. 8 are representable in doubles;
- the ball of the animation stays within its panels' reach (`animation_problems`).

A value given on Snakemake's command line (``--config``), told by comparing the merged
configuration with what the files give, is named as such instead of by a line of a file.
A configuration that passed, unchanged, is not checked again (`CheckRecord`), so that a
no-op ``snakemake`` imports neither jsonschema nor the solution; jsonschema is imported
only where it is used.

Run as a script, ``python workflow/config_checks.py FILE...`` checks that each file exists
and is a YAML mapping: Snakemake reads a ``--configfile`` before the Snakefile, and then
prints a traceback for a missing file and neither file nor line for a syntax error.
``make CONFIGFILE=FILE`` runs this check before ``snakemake --configfile FILE``.
"""

from __future__ import annotations

import datetime
import difflib
import hashlib
import json
import math
import os
import re
import sys
import sysconfig
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

import yaml

if TYPE_CHECKING:  # imported where used: a run whose configuration passed before
    import jsonschema  # (see `CheckRecord`) needs neither
    from referencing import Registry, Resource

ROOT = Path(__file__).resolve().parents[1]

#: Default schema of the configuration.
SCHEMA = ROOT / "workflow" / "schemas" / "config.schema.yaml"

#: Problems listed in full; beyond, the message says how many more there are.
MAX_PROBLEMS = 5

#: Where a value given with Snakemake's ``--config`` is said to come from.
COMMAND_LINE = "--config (command line)"

#: Parameters of the larger model that `turntable fit` fits to a film: the six components
#: of the slipping ball's initial state and its coefficient (`turntable.fit.n_parameters`;
#: tests/test_config_errors.py checks that they agree).
FIT_PARAMETERS = 7

#: Fewest frames the film of section ``film`` may have: two per parameter of the larger fit,
#: its noise variance counted as AIC counts it, 2 (7 + 1) = 16. The fits alone need only
#: more coordinates (two per frame) than parameters, 4 frames; Fig. 8 needs residual degrees
#: of freedom 2 n - 7 > 0 (its F test and expected AIC difference take their logarithm: the
#: 3 frames of 0.01 s at 240 frames/s end in "math domain error"), and a selection by AICc
#: some more (`turntable.fit` may require its own minimum; tests/test_config_errors.py
#: checks that this one is not below it). With 16 frames the 32 coordinates leave 25
#: degrees of freedom, over three per parameter: the estimated noise (relative error about
#: 1 / sqrt(2 * 25) = 14 %) and the standard errors drawn from it mean something.
MIN_FRAMES = 2 * (FIT_PARAMETERS + 1)

#: Most frames: a fit holds its Jacobian, 2 n x 7 doubles (110 MB at 10^6 frames), and
#: evaluates the solution at every frame up to 400 times; Fig. 8 fits every value of its grid.
MAX_FRAMES = 10**6

#: Log-spaced values of mu0 per decade at which a [low, high] range of mu0 is checked
#: against turntable.max_time, besides the peak of alpha1 when it lies inside the range.
RANGE_SAMPLES_PER_DECADE = 32

#: Fewest points per turn 2 pi/beta of the spiral at which a drawn path is a curve: chords
#: of 12 degrees, within 0.6 % of the radius (1 - cos(pi/30)). Fig. 4's last span
#: [0, 1.0e+5] (mu0 = 10, 4500 turns) at 2000 points gives 0.44 per turn.
MIN_POINTS_PER_TURN = 30

#: Most a drawn motion may grow over its span, e^(alpha1 t_end): beyond, its first turns are
#: far below a pixel of the panel and its axes run to powers of ten no reader can place
#: (Fig. 4's span [0, 1.0e+5] for mu0 = 10: 10^101, still representable in doubles).
MAX_GROWTH = 1.0e6

HEADER = "Invalid configuration; nothing was run and no output was changed:"

KeyPath = tuple[str | int, ...]

#: The JSON Schema dialect of the schemas.
DIALECT = "https://json-schema.org/draft/2020-12/schema"


@dataclass(frozen=True)
class Problem:
    """One mistake: the key (or list item) it is about and what is wrong, in words."""

    at: KeyPath
    text: str


# --------------------------------------------------------------------------- files
def file_problem(path: str | os.PathLike[str]) -> str | None:
    """Return why ``path`` is not a readable YAML (or JSON) mapping, or None.

    The message names the file, and for a syntax error the line and column.
    """
    shown = _shown(path)
    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        return f"{shown}: no such configuration file (working directory {Path.cwd()})"
    except (OSError, UnicodeDecodeError) as exc:
        return f"{shown}: cannot read the configuration file ({exc})"
    try:
        data = json.loads(text)
    except ValueError:
        try:
            data = yaml.load(text, Loader=yaml.FullLoader)  # the loader Snakemake uses
        except yaml.MarkedYAMLError as exc:
            mark, start = exc.problem_mark or exc.context_mark, exc.context_mark
            where = f"{shown}:{mark.line + 1}:{mark.column + 1}" if mark else shown
            context = f" ({exc.context}" if exc.context else ""
            if context and start and start.line != mark.line:
                context += f" that starts on line {start.line + 1}"
            return f"{where}: YAML syntax error: {exc.problem}{context + ')' if context else ''}"
        except yaml.YAMLError as exc:
            return f"{shown}: YAML error: {' '.join(str(exc).split())}"
    if not isinstance(data, dict):
        got = "an empty file" if data is None else f"a {type(data).__name__}"
        return f"{shown}: expected sections of keys and values (name: value), got {got}"
    return None


def _shown(path: str | os.PathLike[str]) -> str:
    """``path`` relative to the working directory when it lies below it."""
    p = Path(path)
    if not p.is_absolute():
        return str(p)
    try:
        return str(p.resolve().relative_to(Path.cwd().resolve()))
    except ValueError:
        return str(p)


def merge(config: dict[str, Any], update: Mapping[str, Any]) -> dict[str, Any]:
    """``config`` updated with ``update``, sections merged key by key, as Snakemake merges
    its configuration files and ``--config`` (`snakemake.utils.update_config`)."""
    for key, value in update.items():
        if isinstance(value, Mapping):
            inner = config.get(key)
            config[key] = merge(inner if isinstance(inner, dict) else {}, value)
        else:
            config[key] = value
    return config


def _differ(a: Any, b: Any) -> bool:
    """Whether two configuration values differ, 400 and 400.0 or 1 and true included."""
    if isinstance(a, Mapping) and isinstance(b, Mapping):
        return a.keys() != b.keys() or any(_differ(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) != len(b) or any(_differ(x, y) for x, y in zip(a, b, strict=True))
    return type(a) is not type(b) or (a != b and not (a != a and b != b))  # NaN is NaN


class Sources:
    """Where each key of the merged configuration was written: file and line.

    ``files`` in the order Snakemake merges them (a later file overrides an earlier one).
    Reading them also finds keys given twice in one file, and what the files give together
    (``merged``), so that a value that differs was given on the command line (``--config``).
    """

    def __init__(self, files: Sequence[str | os.PathLike[str]]) -> None:
        self.files = [_shown(f) for f in files]
        self.lines: list[dict[KeyPath, int]] = []
        self.duplicates: list[tuple[tuple[int, int], str]] = []
        self.merged: dict[str, Any] = {}
        for index, f in enumerate(files):
            self.lines.append(self._read(index, f))

    def _read(self, index: int, path: str | os.PathLike[str]) -> dict[KeyPath, int]:
        lines: dict[KeyPath, int] = {}
        try:
            loader = yaml.FullLoader(Path(path).read_text(encoding="utf-8"))  # as Snakemake
            try:
                root = loader.get_single_node()
                data = loader.construct_document(root) if root is not None else None
            finally:
                loader.dispose()
        except (OSError, UnicodeDecodeError, yaml.YAMLError):
            return lines
        if isinstance(data, Mapping):
            merge(self.merged, data)

        def walk(node: yaml.Node, at: KeyPath) -> None:
            if isinstance(node, yaml.MappingNode):
                for key_node, value_node in node.value:
                    key_at = (*at, key_node.value)
                    line = key_node.start_mark.line + 1
                    if key_at in lines:
                        self.duplicates.append(
                            (
                                (index, line),
                                f"{self.files[index]}:{line}: {dotted(key_at)} is given twice "
                                f"(also on line {lines[key_at]}); remove one of them",
                            )
                        )
                    lines[key_at] = line
                    walk(value_node, key_at)
            elif isinstance(node, yaml.SequenceNode):
                for i, item in enumerate(node.value):
                    lines[(*at, i)] = item.start_mark.line + 1
                    walk(item, (*at, i))

        if root is not None:
            walk(root, ())
        return lines

    def from_command_line(self, config: Mapping[str, Any]) -> list[KeyPath]:
        """The keys whose value in ``config`` is not what the files give: ``--config``'s."""

        def walk(value: Any, given: Any, at: KeyPath) -> Iterator[KeyPath]:
            if isinstance(value, Mapping) and isinstance(given, Mapping):
                for key, sub in value.items():
                    if key not in given:
                        yield (*at, key)
                    else:
                        yield from walk(sub, given[key], (*at, key))
            elif _differ(value, given):
                yield at

        return list(walk(config, self.merged, ()))

    def locate(self, at: KeyPath) -> tuple[tuple[int, int], str]:
        """Sort key and ``file:line`` of ``at``, or of the nearest key around it.

        The last file that has the key wins, as in Snakemake's merge.
        """
        for depth in range(len(at), 0, -1):
            for index in reversed(range(len(self.files))):
                line = self.lines[index].get(at[:depth])
                if line is not None:
                    return (index, line), f"{self.files[index]}:{line}"
        if self.files:
            return (len(self.files) - 1, 0), self.files[-1]
        return (0, 0), "configuration"


# --------------------------------------------------------------------------- schema
def _is_int(_checker: Any, value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _is_finite_number(_checker: Any, value: Any) -> bool:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return False
    return math.isfinite(value)


@cache
def validator_class() -> Any:
    """Draft 2020-12 with an integer that is an int and a number that is finite."""
    import jsonschema

    return jsonschema.validators.extend(
        jsonschema.Draft202012Validator,
        type_checker=jsonschema.Draft202012Validator.TYPE_CHECKER.redefine_many(
            {"integer": _is_int, "number": _is_finite_number}
        ),
    )


def _read_schema(path: Path) -> dict[str, Any]:
    schema: dict[str, Any] = yaml.safe_load(path.read_text(encoding="utf-8"))
    # Without "$schema", jsonschema keeps `validator_class()` (and its types) inside this schema
    # instead of switching to the stock validator of the dialect the keyword names.
    if schema.pop("$schema", DIALECT) != DIALECT:
        raise ValueError(f"{path}: expected a JSON Schema of draft 2020-12")
    return schema


@cache
def _retrieve(uri: str) -> Resource:
    """Load a schema that another one refers to by a relative file path."""
    from referencing import Resource
    from referencing.jsonschema import DRAFT202012

    schema = _read_schema(Path(uri.removeprefix("file://")))
    return Resource.from_contents(schema, default_specification=DRAFT202012)


@cache
def load_schema(path: str | os.PathLike[str] = SCHEMA) -> tuple[dict[str, Any], Registry]:
    """The schema at ``path`` (with its file address as ``$id``) and its references."""
    from referencing import Registry, Resource
    from referencing.jsonschema import DRAFT202012

    schema = _read_schema(Path(path))
    schema["$id"] = Path(path).resolve().as_uri()
    resource = Resource.from_contents(schema, default_specification=DRAFT202012)
    registry: Registry = Registry(retrieve=_retrieve).with_resource(schema["$id"], resource)
    return schema, registry


def _follow(schema: Mapping[str, Any], resolver: Any) -> tuple[dict[str, Any], Any]:
    """``schema`` with its ``$ref`` followed (its own keywords win) and the resolver there."""
    out = dict(schema)
    while "$ref" in out:
        found = resolver.lookup(out.pop("$ref"))
        resolver = found.resolver
        out = {**found.contents, **out}
    return out, resolver


def key_schema(at: KeyPath, schema_path: str | os.PathLike[str] = SCHEMA) -> dict[str, Any]:
    """The schema of the key or list item at ``at``, references followed; {} if none."""
    schema, registry = load_schema(schema_path)
    node, resolver = _follow(schema, registry.resolver(base_uri=schema["$id"]))
    for part in at:
        child = node.get("items") if isinstance(part, int) else node.get("properties", {}).get(part)
        if not isinstance(child, Mapping):
            return {}
        node, resolver = _follow(child, resolver)
    return node


def _num(x: float) -> str:
    return str(x) if isinstance(x, int) else f"{x:g}"


def expected(prop: Mapping[str, Any]) -> str:
    """What a value of the schema ``prop`` must be, in words, from its type and bounds."""
    kind = prop.get("type")
    if "enum" in prop:
        return "one of " + ", ".join(str(v) for v in prop["enum"])
    if kind in ("number", "integer"):
        words = "an integer" if kind == "integer" else "a number"
        if "minimum" in prop and "maximum" in prop:
            return f"{words} from {_num(prop['minimum'])} to {_num(prop['maximum'])}"
        bounds = [
            f"{sign} {_num(prop[key])}"
            for key, sign in [
                ("minimum", ">="),
                ("exclusiveMinimum", ">"),
                ("maximum", "<="),
                ("exclusiveMaximum", "<"),
            ]
            if key in prop
        ]
        return f"{words} {' and '.join(bounds)}".strip()
    if kind == "array":
        low, high = prop.get("minItems", 0), prop.get("maxItems")
        count = str(low) if low == high else f"{low} to {high}" if high else f"at least {low}"
        items = prop.get("items")
        each = f", each {expected(items)}" if isinstance(items, Mapping) and "type" in items else ""
        return f"a list of {count} items{each}"
    if kind == "string":
        return f"a text matching {prop['pattern']}" if "pattern" in prop else "a text"
    if kind == "object":
        return "a section of keys and values"
    return "a value of the described kind"


def _yaml_number(text: str) -> str | None:
    """How to write ``text`` so that YAML reads a number, or None if it is not one."""
    m = re.fullmatch(r"\s*([-+]?)(\d+)(?:\.(\d*))?[eE]([-+]?)(\d+)\s*", text)
    if m:
        sign, whole, frac, exp_sign, exp = m.groups()
        return f"{sign}{whole}.{frac or '0'}e{exp_sign or '+'}{exp}"
    try:
        value = float(text)
    except ValueError:
        return None
    return text.strip() if math.isfinite(value) else None


def shown_value(value: Any) -> str:
    """``value`` as it would be written in the configuration, shortened."""
    if isinstance(value, bool):
        return str(value).lower()
    if value is None:
        return "(empty)"
    text = repr(value) if isinstance(value, str) else json.dumps(value, default=str)
    return text if len(text) <= 60 else text[:56] + " ..."


def _wrong_type(value: Any, kind: str | None) -> str:
    """Why ``value`` is not of the schema type ``kind``, with the right spelling if any."""
    if kind in ("number", "integer"):
        if isinstance(value, str):
            spelling = _yaml_number(value)
            if spelling is None:
                return "is text, not a number"
            if re.fullmatch(r"[-+]?\d+", spelling):
                return f"is text, not a number; write {spelling} without quotes"
            if kind == "integer":
                return "is text, not an integer"
            if spelling != value.strip():
                return (
                    f"is text to YAML, not a number; write {spelling} (a number with an "
                    "exponent needs a dot and a signed exponent)"
                )
            return f"is text, not a number; write {spelling} without quotes"
        if isinstance(value, bool):
            return "is a boolean, not a number"
        if isinstance(value, float) and not math.isfinite(value):
            return "is not a finite number"
        if kind == "integer" and isinstance(value, float):
            if value.is_integer():
                return f"is not an integer; write {int(value)}, without a decimal point"
            return "is not a whole number"
    kinds = [
        (dict, "a section"),
        (list, "a list"),
        (str, "a text"),
        (bool, "a boolean"),
        ((int, float), "a number"),
        ((datetime.date, datetime.time), "a date or time"),
        (type(None), "empty"),
    ]
    return "is " + next((name for t, name in kinds if isinstance(value, t)), type(value).__name__)


def _about(prop: Mapping[str, Any]) -> str:
    return " ".join(str(prop.get("description", "")).split())


def _schema_problems(
    err: jsonschema.ValidationError, schema_path: str | os.PathLike[str]
) -> Iterator[Problem]:
    """The problems one schema error stands for (one per unknown or missing key)."""
    at: KeyPath = tuple(err.absolute_path)
    value = err.instance
    inside = f" in {dotted(at)}" if at else ""
    what = "key" if at else "section"
    if err.validator in ("additionalProperties", "required"):
        known = list(err.schema.get("properties", {}))
        unknown = [key for key in value if key not in known]
        missing = [key for key in err.schema.get("required", []) if key not in value]
    if err.validator == "additionalProperties":
        for key in unknown:
            near = difflib.get_close_matches(str(key), missing, n=1)
            if near:
                hint = f"did you mean '{near[0]}' (missing)?"
            else:
                near = difflib.get_close_matches(str(key), known, n=1)
                hint = f"did you mean '{near[0]}'?" if near else "known: " + ", ".join(known)
            yield Problem((*at, key), f"unknown {what} '{key}'{inside}; {hint}")
        return
    if err.validator == "required":
        for key in err.validator_value:
            if key in value or any(
                difflib.get_close_matches(str(u), missing, n=1) == [key] for u in unknown
            ):
                continue  # present, or told as the misspelling of an unknown key
            prop = key_schema((*at, key), schema_path)
            default = f"; default: {shown_value(prop['default'])}" if "default" in prop else ""
            yield Problem(at, f"missing {what} '{key}'{inside} ({_about(prop)}{default})")
        return
    name = dotted(at) if value is None else f"{dotted(at)} = {shown_value(value)}"
    rule = expected(err.schema)
    about = _about(key_schema(at, schema_path)) if at else ""
    about = f" ({about})" if about else ""
    if err.validator == "type":
        yield Problem(at, f"{name} {_wrong_type(value, err.schema.get('type'))}; expected {rule}")
    elif err.validator in ("minItems", "maxItems"):
        yield Problem(at, f"{name} has {len(value)} items; expected {rule}{about}")
    elif err.validator == "uniqueItems":
        yield Problem(at, f"{name} repeats a value; expected all different{about}")
    elif err.validator == "not":
        yield Problem(at, f"{name} is not allowed{about}")
    else:
        yield Problem(at, f"{name}: expected {rule}{about}")


def dotted(at: KeyPath) -> str:
    """The key path ``('fig4_trajectories', 't_span', 1)`` as ``fig4_trajectories.t_span[1]``."""
    out = ""
    for part in at:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


def schema_problems(
    config: Mapping[str, Any], schema_path: str | os.PathLike[str] = SCHEMA
) -> list[Problem]:
    """Problems of type, bounds, missing and unknown keys against the schema."""
    schema, registry = load_schema(schema_path)
    problems: dict[Problem, None] = {}
    for err in validator_class()(schema, registry=registry).iter_errors(config):
        problems.update(dict.fromkeys(_schema_problems(err, schema_path)))
    return list(problems)


# --------------------------------------------------------------------------- conventions
def _items(value: Any, at: KeyPath) -> Iterator[tuple[KeyPath, Any]]:
    """Every key of nested sections, depth first, with its key path."""
    if isinstance(value, Mapping):
        for key, sub in value.items():
            yield (*at, key), sub
            yield from _items(sub, (*at, key))


def _pairs(at: KeyPath, value: Any) -> Iterator[tuple[KeyPath, list[Any]]]:
    """(key path, [start, end]) of a pair, or of each pair of a list of pairs."""
    if value and all(isinstance(v, list) for v in value):
        for i, pair in enumerate(value):
            yield (*at, i), pair
    else:
        yield at, value


def order_problems(config: Mapping[str, Any]) -> list[Problem]:
    """Every key named ``*_span`` or ``*_range`` is an increasing [start, end] pair."""
    return [
        Problem(sub, f"{dotted(sub)} = {shown_value(pair)}: expected [start, end], start < end")
        for at, value in _items(config, ())
        if isinstance(at[-1], str) and at[-1].endswith(("_span", "_range"))
        for sub, pair in _pairs(at, value)
        if not pair[0] < pair[1]
    ]


def name_problems(config: Mapping[str, Any]) -> list[Problem]:
    """In a list of entries that have a ``name`` (each names files), the names differ."""
    found = []
    for at, value in _items(config, ()):
        if not isinstance(value, list):
            continue
        seen: set[Any] = set()
        for i, entry in enumerate(value):
            if isinstance(entry, Mapping) and "name" in entry:
                if entry["name"] in seen:
                    found.append(
                        Problem(
                            (*at, i, "name"),
                            f"{dotted((*at, i, 'name'))} = {shown_value(entry['name'])} is "
                            f"the name of an earlier entry; expected names all different",
                        )
                    )
                seen.add(entry["name"])
    return found


def film_frames(fps: float, duration: float) -> int:
    """Number of frames of a film, as `turntable.film.frame_times` counts them."""
    return math.floor(duration * fps * (1.0 + 1e-12)) + 1


def film_problems(config: Mapping[str, Any]) -> list[Problem]:
    """The film of section ``film`` has from `MIN_FRAMES` to `MAX_FRAMES` frames."""
    section = config.get("film")
    if not isinstance(section, Mapping):
        return []
    fps, duration = section["fps"], section["duration_s"]
    n = film_frames(fps, duration)
    at: KeyPath = ("film", "duration_s")
    given = f"film.duration_s = {duration:g} s at film.fps = {fps:g} frames/s gives {n} frames"
    if n < MIN_FRAMES:
        return [
            Problem(
                at,
                f"{given}, too few to fit both models of turntable fit (7 and 5 parameters); "
                f"expected at least {MIN_FRAMES} frames: duration_s >= "
                f"{(MIN_FRAMES - 1) / fps:.6g}",
            )
        ]
    if n > MAX_FRAMES:
        return [
            Problem(
                at,
                f"{given}; expected at most {MAX_FRAMES} frames (each fit holds 14 numbers "
                f"per frame): duration_s <= {(MAX_FRAMES - 1) / fps:.6g}",
            )
        ]
    return []


def _turntable() -> Any:
    try:
        import turntable
    except ImportError:  # Snakemake run from an environment without the package
        sys.path.append(str(ROOT / "src"))
        import turntable
    import turntable.rolling

    return turntable


def _range_samples(
    tt: Any, low: float, high: float, k: float, end: float | None = None
) -> list[float]:
    """Values of mu0 in [low, high] at which to compare ``end`` with `max_time` and a state.

    A log grid and the peak of alpha1; with ``end``, only those where ``end`` reaches half
    the bound without a state (``max_time(mu0, k)``), worst first: a state lowers the bound
    by ln(size of the solution) / alpha1, less than half of it for any size below 1e154
    (tests/test_config_errors.py checks it over the bounds of the schema).
    """
    import numpy as np

    n = max(2, math.ceil(RANGE_SAMPLES_PER_DECADE * math.log10(high / low)) + 1)
    peak = float(tt.alpha1_peak(k).mu0)
    grid = np.append(np.geomspace(low, high, n), [peak] if low < peak < high else [])
    if end is None:
        return [float(m) for m in grid]
    bound = tt.max_time(grid, k)
    order = np.argsort(bound)
    return [float(m) for m in grid[order][2.0 * end > bound[order]]]


def solution_time_problems(
    config: Mapping[str, Any], schema_path: str | os.PathLike[str] = SCHEMA
) -> list[Problem]:
    """Keys annotated ``x-solution-times`` end where the solution is representable."""
    problems = []
    for section, values in config.items():
        if not isinstance(values, Mapping):
            continue
        for key in values:
            rule = key_schema((section, key), schema_path).get("x-solution-times")
            if rule:
                problems += _solution_times(section, key, values, rule)
    return problems


def _solution_times(
    section: str, key: str, values: Mapping[str, Any], rule: Mapping[str, Any]
) -> list[Problem]:
    tt = _turntable()
    at: KeyPath = (section, key)
    value, mu0 = values[key], values[rule["mu0"]]
    ks = values[rule["k"]] if isinstance(values[rule["k"]], list) else [values[rule["k"]]]
    is_range = rule["mu0"].endswith("_range")
    mu0s = mu0 if isinstance(mu0, list) else [mu0]
    if isinstance(value, list) and value and isinstance(value[0], list):  # one span per mu0
        if is_range or len(value) != len(mu0s):
            return [
                Problem(
                    at,
                    f"{dotted(at)} has {len(value)} spans but {section}.{rule['mu0']} has "
                    f"{len(mu0s)} values; expected one [t_start, t_end] per mu0",
                )
            ]
        pairs = enumerate(zip(value, mu0s, strict=True))
        cases = [((*at, i), span[1], [m]) for i, (span, m) in pairs]
    else:
        cases = [(at, value[1] if isinstance(value, list) else value, mu0s)]
    problems = []
    for where, end, cands in cases:
        problem = _first_unrepresentable(tt, where, end, cands, ks, values, rule, is_range)
        if problem:
            problems.append(problem)
    return problems


def _first_unrepresentable(
    tt: Any,
    at: KeyPath,
    end: float,
    mu0s: list[float],
    ks: list[float],
    values: Mapping[str, Any],
    rule: Mapping[str, Any],
    is_range: bool,
) -> Problem | None:
    state = values[rule["state"]]
    start = f"{at[0]}.{rule['state']}"
    if rule.get("on_constraint"):
        start += " on the no-slip constraint"
    for k in ks:
        z0 = tt.no_slip_state(state, k) if rule.get("on_constraint") else state
        cands = _range_samples(tt, *mu0s, k, end) if is_range else mu0s
        for mu0 in cands:
            limit = float(tt.max_time(mu0, k, z0))
            if end > limit:
                return Problem(
                    at,
                    f"{dotted(at)} ends at t = {end:g}, after t = {limit:.6g}, the last time "
                    f"at which the solution for mu0 = {mu0:.6g}, k = {k:g} from {start} is "
                    f"representable in doubles (turntable.max_time); expected t <= {limit:.6g}",
                )
        if rule.get("rolling"):
            comparison = values[rule["rolling"]]
            for mu0 in _range_samples(tt, *mu0s, k) if is_range else mu0s:
                delta = float(tt.rolling.matched_delta(mu0, k, comparison))
                try:
                    tt.rolling.solve(z0, [end], delta, k)
                except ValueError as exc:
                    return Problem(
                        at,
                        f"{dotted(at)} ends at t = {end:g}, too late for the rolling ball "
                        f"(delta = {delta:.6g}, {comparison}, k = {k:g}): {exc}",
                    )
    return None


def drawing_problems(
    config: Mapping[str, Any], schema_path: str | os.PathLike[str] = SCHEMA
) -> list[Problem]:
    """Spans annotated ``x-drawn`` (with their ``x-solution-times``) keep the motion readable:
    at most one problem per span and kind (too few points per turn, too much growth)."""
    problems = []
    for section, values in config.items():
        if not isinstance(values, Mapping):
            continue
        for key in values:
            prop = key_schema((section, key), schema_path)
            if "x-drawn" in prop:
                problems += _drawing(section, key, values, prop, schema_path)
    return problems


def _drawing(
    section: str,
    key: str,
    values: Mapping[str, Any],
    prop: Mapping[str, Any],
    schema_path: str | os.PathLike[str],
) -> list[Problem]:
    tt = _turntable()
    times, drawn = prop["x-solution-times"], prop["x-drawn"]
    at: KeyPath = (section, key)
    value, k, mu0 = values[key], values[times["k"]], values[times["mu0"]]
    mu0s = mu0 if isinstance(mu0, list) else [mu0]
    if isinstance(value[0], list):  # one span per mu0 (their number is checked before)
        cases = [((*at, i), span, [m]) for i, (span, m) in enumerate(zip(value, mu0s, strict=True))]
    else:
        cases = [(at, value, mu0s)]
    count_key = drawn.get("n_points")
    n = values[count_key] if count_key else None
    problems = []
    for where, (t0, t1), cands in cases:
        # (what, its growth rate and the rate's name, its fastest angular frequency) of every
        # motion drawn
        motions = []
        for m in cands:
            s = tt.spectrum(m, k)
            motions.append(
                (f"the slipping ball (mu0 = {m:g})", float(s.alpha1), "alpha1", float(s.beta))
            )
            if times.get("rolling"):
                delta = float(tt.rolling.matched_delta(m, k, values[times["rolling"]]))
                r = tt.rolling.spectrum(delta, k)
                rate, freq = float(r.sigma_g), max(abs(float(r.nu_g)), abs(float(r.nu_c)))
                motions.append((f"the rolling ball (delta = {delta:.3g})", rate, "sigma_g", freq))
        span = f"{dotted(where)} = [{t0:g}, {t1:g}]"
        if n is not None:
            turns, what = max(
                (freq * (t1 - t0) / (2 * math.pi), what) for what, *_, freq in motions
            )
            if n - 1 < MIN_POINTS_PER_TURN * turns:
                needed = math.ceil(MIN_POINTS_PER_TURN * turns) + 1
                most = key_schema((section, count_key), schema_path).get("maximum", needed)
                more = f"{count_key} >= {needed}, or " if needed <= most else ""
                longest = (n - 1) / MIN_POINTS_PER_TURN * (t1 - t0) / turns
                problems.append(
                    Problem(
                        where,
                        f"{span}, drawn at {section}.{count_key} = {n} points, holds {turns:.4g} "
                        f"turns of {what}: {(n - 1) / turns:.2g} points per turn; "
                        f"expected at least {MIN_POINTS_PER_TURN} per turn: {more}a span at "
                        f"most {longest:.4g} long",
                    )
                )
        rate, name, what = max((rate, name, what) for what, rate, name, _ in motions)
        if rate * t1 > math.log(MAX_GROWTH):
            problems.append(
                Problem(
                    where,
                    f"{span}: by t = {t1:g}, {what} has grown by e^({name} t) = "
                    f"10^{rate * t1 / math.log(10):.3g} ({name} = {rate:.3g}), more than a "
                    f"figure can show; expected a growth of at most {MAX_GROWTH:.0e} ({name} "
                    f"t_end <= {math.log(MAX_GROWTH):.3g}): t_end <= "
                    f"{math.log(MAX_GROWTH) / rate:.4g}",
                )
            )
    return problems


def film_time_problems(config: Mapping[str, Any]) -> list[Problem]:
    """The film of section ``film`` ends where every motion it is compared with is
    representable: each synthetic film (section ``synthetic_film``), and, over the range of
    Fig. 8 (section ``fig8_measurability``), the slipping ball for each mu0 and the rolling
    ball for delta = mu0, all from the film's start (the rolling ball's on the no-slip
    constraint), until t Omega = Omega (n - 1) / fps."""
    section = config.get("film")
    if not isinstance(section, Mapping):
        return []
    tt = _turntable()
    from turntable import film

    try:
        rig = film.rig_from_config(section)
    except ValueError as exc:
        return [Problem(("film",), f"film: {exc}")]
    n = film_frames(section["fps"], section["duration_s"])
    omega, k = rig.setup.omega, rig.setup.k
    end = omega * (n - 1) / section["fps"]
    start = {"slipping": rig.state0, "rolling_resistance": tt.no_slip_state(rig.state0, k)}
    # (model, coefficients, what they are)
    cases = [
        (spec["model"], [spec["coefficient"]], f"synthetic film '{spec['name']}'")
        for spec in config.get("synthetic_film", {}).get("films", [])
    ]
    fig8 = config.get("fig8_measurability")
    if isinstance(fig8, Mapping):
        low, high = fig8["mu0_range"]
        cases += [
            ("slipping", _range_samples(tt, low, high, k, end), "Fig. 8"),
            ("rolling_resistance", _rolling_samples(tt, low, high, k, end), "Fig. 8"),
        ]
    shown = (
        f"film.duration_s = {section['duration_s']:g} s at film.rpm = {section['rpm']:g} "
        f"ends at t Omega = {end:.6g}"
    )
    for model, coefficients, what in cases:
        z0 = start[model]
        for c in coefficients:
            if model == "slipping":
                limit = float(tt.max_time(c, k, z0))
                if end > limit:
                    return [
                        Problem(
                            ("film", "duration_s"),
                            f"{shown}, after t Omega = {limit:.6g}, the last time at which the "
                            f"slipping ball of {what} (mu0 = {c:.6g}) is representable in "
                            f"doubles (turntable.max_time); expected duration_s <= "
                            f"{limit / omega:.6g}",
                        )
                    ]
            else:
                try:
                    tt.rolling.solve(z0, [end], c, k)
                except ValueError as exc:
                    return [
                        Problem(
                            ("film", "duration_s"),
                            f"{shown}, too late for the rolling ball of {what} "
                            f"(delta = {c:.6g}, Omega = {omega:.6g} rad/s): {exc}",
                        )
                    ]
    return []


def _rolling_samples(tt: Any, low: float, high: float, k: float, end: float) -> list[float]:
    """Values of delta in [low, high] at which the rolling ball might not be representable
    at ``end``: a log grid, fastest growth first, those whose growth alone reaches half the
    exponent range of a double (as `_range_samples` for the slipping ball)."""
    import numpy as np

    n = max(2, math.ceil(RANGE_SAMPLES_PER_DECADE * math.log10(high / low)) + 1)
    grid = np.geomspace(low, high, n)
    rate = np.asarray(tt.rolling.growth_rate(grid, k), dtype=float)
    order = np.argsort(-rate)
    half = 0.5 * math.log(sys.float_info.max)
    return [float(d) for d in grid[order][rate[order] * end > half]]


def animation_problems(config: Mapping[str, Any]) -> list[Problem]:
    """The ball of the animation (section ``animation``) is drawn at least two pixels wide:
    the panels show a disc of half-width `extent` = 1.5 R + the farthest the centre goes
    from the axis, both balls, over the frames, in ``size`` pixels, so that extent must be
    at most size / 2 (the ball's radius R then at least a pixel). Beyond, the ball is not
    seen, and the panel draws a ring every 2 R: a ball that grows to 1e30 R never ends."""
    a = config.get("animation")
    if not isinstance(a, Mapping):
        return []
    tt = _turntable()
    import numpy as np

    t = np.linspace(0.0, a["t_end"], (a["n_frames"] - 1) * a["substeps"] + 1)
    paths = [tt.solve(a["state"], t, a["mu0"], a["k"]), tt.nonholonomic(a["state"], t, a["k"])]
    extent = 1.5 + max(float(np.max(np.hypot(z[:, 0], z[:, 1]))) for z in paths)
    if extent <= a["size"] / 2:
        return []
    return [
        Problem(
            ("animation", "t_end"),
            f"animation.t_end = {a['t_end']:g}: by then the ball goes {extent - 1.5:.4g} R "
            f"from the axis, so that in panels of animation.size = {a['size']} pixels it "
            f"would be drawn {a['size'] / extent:.2g} pixels wide; expected at most "
            f"size / 2 - 1.5 = {a['size'] / 2 - 1.5:g} R from the axis (an earlier t_end, a "
            "state nearer the axis, or a larger size)",
        )
    ]


# --------------------------------------------------------------------------- all checks
def problems(
    config: Mapping[str, Any], schema_path: str | os.PathLike[str] = SCHEMA
) -> list[Problem]:
    """Every problem of ``config``; each stage runs only when the earlier ones found none."""
    if not isinstance(config, Mapping):
        return [Problem((), f"expected sections of keys and values, got {shown_value(config)}")]
    for stage in (
        lambda: schema_problems(config, schema_path),
        lambda: order_problems(config),
        lambda: name_problems(config),
        lambda: film_problems(config),
        lambda: solution_time_problems(config, schema_path),
        lambda: film_time_problems(config) + animation_problems(config),
        lambda: drawing_problems(config, schema_path),
    ):
        found = stage()
        if found:
            return found
    return []


def config_problem(
    config: Mapping[str, Any],
    files: Sequence[str | os.PathLike[str]],
    schema_path: str | os.PathLike[str] = SCHEMA,
) -> str | None:
    """The message with which the workflow refuses ``config``, or None if it is valid.

    Parameters
    ----------
    config : mapping
        The merged configuration (Snakemake's ``config``).
    files : sequence of path
        The configuration files it was merged from, in order (a later one overrides an
        earlier one); used to name the file and line of each problem.
    schema_path : path, optional
        The JSON schema (YAML) of the configuration.

    Returns
    -------
    str or None
        A header and one line per problem, sorted by file and line, at most
        `MAX_PROBLEMS` of them. A value that is not what the files give came from
        Snakemake's ``--config``, and is told as such, after the files.
    """
    existing = [f for f in files if Path(f).is_file()]
    sources = Sources(existing)
    lines = list(sources.duplicates)
    given = sources.from_command_line(config)
    for problem in problems(config, schema_path):
        text = problem.text
        if any(problem.at[: len(at)] == at for at in given):
            order, where = (len(existing), 0), COMMAND_LINE
            if " is text" in text:  # --config reads the values inside {...} as text
                text += (
                    " (--config reads the values of a section as text: write them in a "
                    "file and pass it with --configfile)"
                )
        else:
            order, where = sources.locate(problem.at)
        lines.append((order, f"{where}: {text}"))
    if not lines:
        return None
    texts = [text for _, text in sorted(lines, key=lambda x: x[0])]
    more = len(texts) - MAX_PROBLEMS
    shown = texts[:MAX_PROBLEMS] + ([f"(and {more} more)"] if more > 0 else [])
    return "\n".join([HEADER, *shown])


# --------------------------------------------------------------------------- checked before
#: Where the working directory remembers the last configuration that passed every check
#: (in Snakemake's own folder, which `make clean` removes): see `CheckRecord`.
RECORD = Path(".snakemake") / "config_checks.ok"


def _what_the_checks_read() -> Iterator[Path]:
    """The files whose contents decide the checks besides the configuration: this module,
    the schemas, and the package whose solution bounds the time spans."""
    yield Path(__file__).resolve()
    yield from sorted((ROOT / "workflow" / "schemas").glob("*.yaml"))
    package = ROOT / "src" / "turntable"
    yield from sorted(p for p in package.rglob("*") if p.suffix in (".py", ".yaml"))


class CheckRecord:
    """Skips the checks of a configuration that passed them before, unchanged.

    A no-op ``snakemake`` would otherwise spend a tenth of its time on them (importing
    jsonschema, validating, evaluating the solution's bounds). The record holds two
    SHA-256 digests: of the configuration files' bytes together with everything else the
    checks read (this module, the schemas, the package's sources, the Python version and
    the state of the installed packages, through the modification time of site-packages,
    which any install or removal changes), and of the same with the merged configuration
    (``--config`` included). Only a configuration that passed is recorded; any change of
    any of those inputs misses the record and runs every check again.
    """

    def __init__(self, files: Sequence[str | os.PathLike[str]], path: Path = RECORD) -> None:
        self.path = path
        digest = hashlib.sha256(f"{sys.version}\0".encode())
        purelib = Path(sysconfig.get_paths()["purelib"])
        digest.update(f"{purelib}:{_mtime(purelib)}\0".encode())
        for f in [*_what_the_checks_read(), *map(Path, files)]:
            digest.update(f"{f}\0".encode())
            try:
                digest.update(f.read_bytes())
            except OSError:
                digest.update(b"\0missing\0")
        self.files_digest = digest.hexdigest()
        self._digest = digest
        try:
            self.recorded = path.read_text().split()
        except (OSError, UnicodeDecodeError):
            self.recorded = []

    def files_checked(self) -> bool:
        """Whether these very files passed every check before."""
        return self.recorded[:1] == [self.files_digest]

    def _config_digest(self, config: Mapping[str, Any]) -> str:
        digest = self._digest.copy()
        digest.update(repr(config).encode())  # repr: 400 and 400.0, 1 and True differ
        return digest.hexdigest()

    def checked(self, config: Mapping[str, Any]) -> bool:
        """Whether this configuration, from these files, passed every check before."""
        return self.recorded == [self.files_digest, self._config_digest(config)]

    def record(self, config: Mapping[str, Any]) -> None:
        """Remember that ``config`` passed (a failure to write only costs the next check)."""
        text = f"{self.files_digest}\n{self._config_digest(config)}\n"
        tmp = self.path.with_name(f".{self.path.name}.{os.getpid()}")
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            tmp.write_text(text)
            os.replace(tmp, self.path)
        except OSError:
            tmp.unlink(missing_ok=True)


def _mtime(path: Path) -> int:
    try:
        return path.stat().st_mtime_ns
    except OSError:
        return 0


def workflow_problem(
    config: Mapping[str, Any],
    files: Sequence[str | os.PathLike[str]],
    record: CheckRecord | None = None,
) -> str | None:
    """`config_problem`, skipped when ``record`` says this configuration passed before."""
    if record is not None and record.checked(config):
        return None
    problem = config_problem(config, files)
    if problem is None and record is not None:
        record.record(config)
    return problem


def main(argv: Sequence[str]) -> int:
    """Check that each configuration file of ``argv`` exists and is a YAML mapping."""
    found = [p for p in (file_problem(f) for f in argv) if p]
    for problem in found:
        print(problem, file=sys.stderr)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
