"""Data types, parameters and the registry mechanism of the claims checks."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np
from numpy.typing import NDArray

Verdict = Literal["confirmed", "refined", "corrected", "undecidable", "failed"]

#: The three verdicts, from best to worst.
VERDICTS: tuple[Verdict, ...] = ("confirmed", "refined", "corrected", "undecidable", "failed")

#: Significant digits kept for every float written to the report.
SIGNIFICANT_DIGITS = 12

#: Parameters of the checks, with the values used when a key is not given.
DEFAULT_PARAMS: dict[str, Any] = {
    "k_paper": 0.4,
    "k_values": [0.05, 0.4, 0.6666666666666666, 1.0],
    "mu0_range": [1.0e-6, 1.0e6],
    "n_points": 241,
    "mu0_probe": [1.0e-4, 1.0e-2, 0.1, 1.0, 10.0, 1.0e3, 1.0e6],
    "mu0_small": [1.0e-6, 1.0e-8, 1.0e-10],
    "mu0_reference": [0.1, 1.0, 10.0],
    "mu0_fig3": [0.1, 1.0],
    "mu0_spiral": [0.02, 0.0793, 0.3, 1.0, 10.0],
    "mu0_limit": [10.0, 100.0, 1000.0, 10000.0],
    "mu0_newton_euler": 0.5,
    "t_newton_euler": 4.0,
    "t_limit": 10.0,
    "state_fig3": [1.0, 1.0, 0.0, 0.0, 0.0, 0.0],
    "state_fig4": [1.0, 1.0, 0.0, 0.0, 0.0, 1.0],
    "n_states": 4,
    "seed": 20190206,
}


def _fail(key: str, what: str, value: Any) -> None:
    raise ValueError(f"params[{key!r}] must be {what}; got {value!r}")


def _positive(key: str, value: Any) -> float:
    ok = isinstance(value, (int, float)) and not isinstance(value, bool)
    if not ok or not math.isfinite(value) or value <= 0:
        _fail(key, "a finite number > 0", value)
    return float(value)


def _positive_list(key: str, value: Any, *, min_items: int = 1) -> list[float]:
    if not isinstance(value, (list, tuple)) or len(value) < min_items:
        _fail(key, f"a list of at least {min_items} finite numbers > 0", value)
    return [_positive(f"{key}[{i}]", v) for i, v in enumerate(value)]


def _integer(key: str, value: Any, low: int, high: int) -> int:
    if not isinstance(value, int) or isinstance(value, bool) or not low <= value <= high:
        _fail(key, f"an integer in [{low}, {high}]", value)
    return int(value)


def _state(key: str, value: Any) -> list[float]:
    if not isinstance(value, (list, tuple)) or len(value) != 6:
        _fail(key, "six finite numbers [x, y, vx, vy, wx, wy]", value)
    out = []
    for v in value:
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
            _fail(key, "six finite numbers [x, y, vx, vy, wx, wy]", value)
        out.append(float(v))
    return out


def resolve_params(params: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """Return the check parameters: ``params`` over `DEFAULT_PARAMS`, validated.

    Parameters
    ----------
    params : mapping, optional
        Any subset of the keys of `DEFAULT_PARAMS` (for instance the
        ``claims:`` section of ``config/config.yaml``).

    Returns
    -------
    dict
        Every key of `DEFAULT_PARAMS`, with floats, ints and lists of floats.

    Raises
    ------
    ValueError
        For an unknown key or a value of the wrong type or range; the message
        names the key.
    """
    given = dict(params or {})
    unknown = sorted(set(given) - set(DEFAULT_PARAMS))
    if unknown:
        raise ValueError(f"unknown claims parameter(s) {unknown}; known: {sorted(DEFAULT_PARAMS)}")
    p = {**DEFAULT_PARAMS, **given}
    out: dict[str, Any] = {}
    out["k_paper"] = _positive("k_paper", p["k_paper"])
    out["k_values"] = _positive_list("k_values", p["k_values"])
    grid = _positive_list("mu0_range", p["mu0_range"], min_items=2)
    if len(grid) != 2 or not grid[0] < grid[1]:
        _fail("mu0_range", "[low, high] with 0 < low < high", p["mu0_range"])
    out["mu0_range"] = grid
    out["n_points"] = _integer("n_points", p["n_points"], 16, 100000)
    for key in ("mu0_probe", "mu0_reference", "mu0_fig3", "mu0_spiral"):
        out[key] = _positive_list(key, p[key])
    out["mu0_small"] = _positive_list("mu0_small", p["mu0_small"], min_items=2)
    if max(out["mu0_small"]) > 1e-3:
        _fail("mu0_small", "a list of at least two values <= 1e-3", p["mu0_small"])
    out["mu0_limit"] = _positive_list("mu0_limit", p["mu0_limit"], min_items=3)
    if min(out["mu0_limit"]) < 1.0:
        _fail("mu0_limit", "a list of at least three values >= 1", p["mu0_limit"])
    for key in ("mu0_newton_euler", "t_newton_euler", "t_limit"):
        out[key] = _positive(key, p[key])
    out["state_fig3"] = _state("state_fig3", p["state_fig3"])
    out["state_fig4"] = _state("state_fig4", p["state_fig4"])
    out["n_states"] = _integer("n_states", p["n_states"], 1, 100)
    out["seed"] = _integer("seed", p["seed"], 0, 2**32 - 1)
    return out


def mu0_grid(params: Mapping[str, Any]) -> NDArray[np.float64]:
    """Return the log-spaced grid of mu0 described by ``mu0_range`` and ``n_points``."""
    low, high = params["mu0_range"]
    return np.logspace(np.log10(low), np.log10(high), params["n_points"])


def random_states(params: Mapping[str, Any]) -> NDArray[np.float64]:
    """Return ``n_states`` reproducible generic states, shape (n_states, 6).

    Components are uniform in [-1, 1], drawn from ``numpy.random.default_rng(seed)``;
    the x-velocity is kept away from 0 so that a sign error in it is visible.
    """
    rng = np.random.default_rng(params["seed"])
    z = rng.uniform(-1.0, 1.0, size=(params["n_states"], 6))
    z[:, 2] = np.where(z[:, 2] >= 0, 0.25 + 0.75 * z[:, 2], -0.25 + 0.75 * z[:, 2])
    return z


@dataclass(frozen=True)
class Where:
    """Location of a claim in the paper."""

    section: str
    equations: str = ""
    figure: str = ""

    def label(self) -> str:
        """Return a short human-readable location, e.g. ``Sec. 2, (2.8), Fig. 4``."""
        parts = [self.section, self.equations, self.figure]
        return ", ".join(p for p in parts if p)


@dataclass(frozen=True)
class Outcome:
    """What a check function returns.

    Attributes
    ----------
    verdict : {"confirmed", "refined", "failed"}
        Decided from the numbers in ``reproduced``.
    reproduced : dict
        Named reproduced values (floats, ints, bools, strings, lists, dicts).
    tolerance : dict
        Named tolerances against which the verdict was decided.
    summary : str
        One line for the table: the main reproduced numbers.
    evidence : str
        Why the verdict is what it is; for ``refined``, the precise form that
        holds.
    """

    verdict: Verdict
    reproduced: dict[str, Any]
    tolerance: dict[str, Any]
    summary: str
    evidence: str


@dataclass(frozen=True)
class Claim:
    """One claim of the paper (or of the project) and the function that checks it.

    Attributes
    ----------
    id : str
        Stable identifier, e.g. ``"solution.centre"``.
    where : Where
        Section, equations and figure of the paper.
    claim : str
        The claim in one sentence.
    paper_value : dict or None
        What the paper states numerically (``{"text": ..., <name>: <number>}``),
        or None when the paper states no number.
    method : str
        How the check computes its reproduced values.
    check : callable
        ``check(params) -> Outcome``.
    source : str
        ``"paper"`` for a claim of the paper, ``"project"`` for one the
        reproduction adds.
    """

    id: str
    where: Where
    claim: str
    paper_value: dict[str, Any] | None
    method: str
    check: Callable[[dict[str, Any]], Outcome] = field(repr=False)
    source: str = "paper"


_REGISTRY: dict[str, Claim] = {}


def register(
    id: str,
    *,
    where: Where,
    claim: str,
    paper_value: dict[str, Any] | None,
    method: str,
    source: str = "paper",
) -> Callable[[Callable[[dict[str, Any]], Outcome]], Callable[[dict[str, Any]], Outcome]]:
    """Decorator that adds a check function to the registry under ``id``."""

    def wrap(fn: Callable[[dict[str, Any]], Outcome]) -> Callable[[dict[str, Any]], Outcome]:
        if id in _REGISTRY:
            raise ValueError(f"claim id {id!r} registered twice")
        _REGISTRY[id] = Claim(id, where, claim, paper_value, method, fn, source)
        return fn

    return wrap


def registered() -> Iterator[Claim]:
    """Yield the registered claims in registration order."""
    yield from _REGISTRY.values()


def verdict_from(ok: bool, refined: bool = False) -> Verdict:
    """Return ``failed`` unless ``ok``; else ``refined`` or ``confirmed``."""
    if not ok:
        return "failed"
    return "refined" if refined else "confirmed"


def sig(x: float, digits: int = 4) -> str:
    """Format a number with ``digits`` significant digits for a summary line."""
    return f"{float(x):.{digits}g}"


def clean(value: Any) -> Any:
    """Return ``value`` with numpy types made plain and floats rounded.

    Floats keep `SIGNIFICANT_DIGITS` significant digits (so that the report
    does not carry rounding noise), written by ``repr``; non-finite floats
    raise, since JSON cannot hold them.
    """
    if isinstance(value, Mapping):
        return {str(k): clean(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [clean(v) for v in value]
    if isinstance(value, np.ndarray):
        return clean(value.tolist())
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        x = float(value)
        if not math.isfinite(x):
            raise ValueError(f"non-finite value {x!r} in a claims report")
        return float(f"{x:.{SIGNIFICANT_DIGITS}g}") + 0.0
    if value is None or isinstance(value, str):
        return value
    raise TypeError(f"cannot write {type(value).__name__} to a claims report")
