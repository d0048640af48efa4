"""Data types, parameters and the registry mechanism of the claims checks."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any, Literal

import numpy as np

Verdict = Literal["confirmed", "refined", "corrected", "undecidable", "failed"]

#: The verdicts, from best to worst (their meaning: `turntable.claims`).
VERDICTS: tuple[Verdict, ...] = ("confirmed", "refined", "corrected", "undecidable", "failed")

#: Significant digits kept for every float written to the report.
SIGNIFICANT_DIGITS = 12


@dataclass(frozen=True)
class Where:
    """Location of a claim in the paper.

    Examples
    --------
    >>> from turntable import claims
    >>> where = claims.get("solution.centre").where
    >>> where
    Where(section='Sec. 2', equations='(2.8)', figure='Fig. 4')
    >>> where.label()
    'Sec. 2, (2.8), Fig. 4'
    """

    section: str
    equations: str = ""
    figure: str = ""

    def label(self) -> str:
        """Return a short human-readable location, e.g. ``Sec. 2, (2.8), Fig. 4``."""
        parts = [self.section, self.equations, self.figure]
        return ", ".join(p for p in parts if p)


#: Relations a tolerance can state between a reproduced value and its bound.
RELATIONS: dict[str, Callable[[float, float], bool]] = {
    "<=": lambda x, b: x <= b,
    "<": lambda x, b: x < b,
    ">=": lambda x, b: x >= b,
    ">": lambda x, b: x > b,
    "==": lambda x, b: x == b,
}


def split_bound(bound: Any) -> tuple[str, Any]:
    """Return (relation, limit) of a tolerance entry: a number means ``<=``."""
    if isinstance(bound, Mapping):
        if len(bound) != 1 or next(iter(bound)) not in RELATIONS:
            raise ValueError(f"a bound is a number or {{relation: limit}}; got {bound!r}")
        return next(iter(bound.items()))
    return "<=", bound


def within(value: Any, bound: Any) -> bool:
    """Return whether a reproduced value (or every element of a list of them) meets its bound.

    ``bound`` is a number (the value must be at most that) or a one-entry mapping
    ``{relation: limit}`` with a relation of `RELATIONS`, e.g. ``{">": 0.0}``.
    """
    relation, limit = split_bound(bound)
    if isinstance(value, (list, tuple, np.ndarray)):
        return all(within(v, bound) for v in value)
    return bool(RELATIONS[relation](value, limit))


def all_within(reproduced: Mapping[str, Any], tolerance: Mapping[str, Any]) -> bool:
    """Return whether every reproduced value named in ``tolerance`` meets its bound."""
    return all(within(reproduced[key], bound) for key, bound in tolerance.items())


#: How a number is reduced over the parameters of its ``over``: the smallest, the largest,
#: one value for each (a list, in the order of ``over``), or the distinct values (sorted).
Reduction = Literal["min", "max", "each", "set"]


@dataclass(frozen=True)
class Quantity:
    """What a reproduced number is: one record for the report, the claims table and the article.

    The article prints a number with the parameters of its record, so that its prose cannot
    say "at k = 0.4" of a number reduced over every k.

    Attributes
    ----------
    of : str
        What the number measures, in words.
    at : dict
        The parameters held fixed, name to value, e.g. ``{"mu0": 1e4}``.
    over : dict
        The parameters the number is reduced over, name to the values tried.
    reduce : {"min", "max", "each", "set"} or None
        The reduction over ``over``; None when ``over`` is empty.

    Examples
    --------
    >>> q = Quantity("distance of the maps onto u = 0", at={"mu0": 1e4},
    ...              over={"k": [0.05, 0.4]}, reduce="min")
    >>> q.label()
    'at mu0 = 10000; smallest over k in {0.05, 0.4}'
    >>> Quantity("a rate", over={"k": [0.4]})
    Traceback (most recent call last):
    ...
    ValueError: a Quantity reduced over ['k'] needs reduce: one of ('min', 'max', 'each', 'set')
    """

    of: str
    at: dict[str, Any] = field(default_factory=dict)
    over: dict[str, Any] = field(default_factory=dict)
    reduce: Reduction | None = None

    def __post_init__(self) -> None:
        reductions = ("min", "max", "each", "set")
        if bool(self.over) != (self.reduce is not None) or self.reduce not in (None, *reductions):
            raise ValueError(
                f"a Quantity reduced over {sorted(self.over)} needs reduce: one of {reductions}"
                if self.over
                else f"a Quantity with reduce={self.reduce!r} needs the values it is reduced over"
            )

    def label(self) -> str:
        """Return the parameters in words, e.g. ``at k = 0.4; largest over mu0 in {1, 10}``."""
        parts = []
        if self.at:
            parts.append("at " + ", ".join(f"{n} = {_short(v)}" for n, v in self.at.items()))
        if self.over:
            word = {
                "min": "smallest",
                "max": "largest",
                "each": "one for each",
                "set": "the distinct values",
            }[self.reduce]
            ranges = " and ".join(
                f"{n} in {{{', '.join(_short(x) for x in np.ravel(v))}}}"
                for n, v in self.over.items()
            )
            parts.append(f"{word} over {ranges}")
        return "; ".join(parts)

    def record(self) -> dict[str, Any]:
        """Return the record as plain data, for results/claims.json."""
        return {"of": self.of, "at": self.at, "over": self.over, "reduce": self.reduce}


def _short(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.6g}" if value.is_integer() else f"{value:.4g}"
    return str(value)


@dataclass(frozen=True)
class Outcome:
    """What a check function returns.

    Attributes
    ----------
    verdict : str
        One of `VERDICTS`, decided from the numbers in ``reproduced``.
    reproduced : dict
        Named reproduced values (floats, ints, bools, strings, lists, dicts).
    tolerance : dict
        The bounds against which the verdict was decided, under the key of the
        reproduced value each bounds: a number (the value is at most that) or
        ``{relation: limit}`` (see ``within``). Every key is a key of ``reproduced``.
        Unless the verdict is ``failed`` every bound holds: what makes a verdict
        ``refined``, ``corrected`` or ``undecidable`` is stated as a bound that holds.
    summary : str
        One line for the table: the main reproduced numbers.
    evidence : str
        Why the verdict is what it is; for ``refined``, the precise form that
        holds; for ``corrected``, the corrected formula.
    quantities : dict
        What the reproduced values the article prints are (`Quantity`), under their keys.

    Examples
    --------
    >>> from turntable import claims
    >>> outcome = claims.get("spectrum.kernel").check(claims.resolve_params())
    >>> outcome.verdict, all(name in outcome.reproduced for name in outcome.tolerance)
    ('confirmed', True)
    """

    verdict: Verdict
    reproduced: dict[str, Any]
    tolerance: dict[str, Any]
    summary: str
    evidence: str
    quantities: dict[str, Quantity] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for name, keys in (("tolerance", self.tolerance), ("quantities", self.quantities)):
            missing = sorted(set(keys) - set(self.reproduced))
            if missing:
                raise ValueError(f"{name} keys without a reproduced value: {missing}")
        for bound in self.tolerance.values():
            split_bound(bound)


@dataclass(frozen=True)
class Claim:
    """One claim of the paper (or of the project) and the function that checks it.

    Attributes
    ----------
    id : str
        Stable identifier, e.g. ``"solution.centre"``.
    where : Where
        Section, equations and figure of the paper (for an addition of the
        reproduction: what in the paper it builds on).
    claim : str
        The claim in one sentence.
    paper_value : dict
        What the paper states (``{"text": ..., <name>: <number>}``): a number, an
        inequality, a formula or a qualitative statement; for an addition, what
        the paper states that it builds on.
    method : str
        How the check computes its reproduced values.
    check : callable
        ``check(params) -> Outcome``.
    expected : str
        The verdict the check is expected to reach with the configured parameters
        (one of `VERDICTS`); the tests require exactly this verdict.
    source : str
        ``"paper"`` for a claim of the paper, ``"project"`` for one the
        reproduction adds.
    gist : str
        What the check establishes, in a few words, when it reaches the ``expected``
        verdict (the article lists claims by verdict with this line; with another
        verdict it shows the ``summary`` instead).
    decisive : str
        The key of the one reproduced value, with its bound in the ``tolerance``, that
        decides the ``expected`` verdict (``turntable claims`` prints it, one line per
        claim).

    Examples
    --------
    >>> from turntable import claims
    >>> claim = claims.get("solution.centre")
    >>> claim.source, claim.expected
    ('paper', 'corrected')
    """

    id: str
    where: Where
    claim: str
    paper_value: dict[str, Any]
    method: str
    check: Callable[[dict[str, Any]], Outcome] = field(repr=False)
    expected: Verdict = "confirmed"
    source: str = "paper"
    gist: str = ""
    decisive: str = ""

    def label(self) -> str:
        """Return the location; an addition of the reproduction is marked as such."""
        if self.source == "project":
            return f"addition (from {self.where.label()})"
        return self.where.label()


_REGISTRY: dict[str, Claim] = {}


def register(
    id: str,
    *,
    where: Where,
    claim: str,
    paper_value: dict[str, Any],
    method: str,
    expected: Verdict,
    decisive: str,
    gist: str = "",
    source: str = "paper",
) -> Callable[[Callable[[dict[str, Any]], Outcome]], Callable[[dict[str, Any]], Outcome]]:
    """Decorator that adds a check function to the registry under ``id``.

    The order of registration is the order of the report (the paper's order): the
    check modules are imported in the paper's order and register their claims in it.
    Everything the report, the tests and the article say of a claim comes from here:
    adding a claim is one call.

    Parameters
    ----------
    id : str
        Stable identifier, ``"<part>.<name>"``.
    where, claim, paper_value, method, source
        The attributes of the same names of `Claim`.
    expected : str
        The verdict the tests require of the check (one of `VERDICTS`).
    decisive : str
        The key of the reproduced value whose bound decides that verdict
        (`turntable.claims.evaluate` refuses a check whose tolerance does not bound it).
    gist : str, optional
        What the check establishes then, in a few words.

    Returns
    -------
    callable
        The decorator, which registers ``check(params) -> Outcome`` and returns it.

    Examples
    --------
    The form of a registration (a claim of the registry, so refused as a second one):

    >>> from turntable.claims import Where, register
    >>> decorator = register(
    ...     "spectrum.kernel",
    ...     where=Where("Sec. 2", "(2.3)"),
    ...     claim="L has a two-dimensional kernel.",
    ...     paper_value={"text": "a plane of equilibria"},
    ...     method="Ranks of L at many (mu0, k).",
    ...     expected="confirmed",
    ...     decisive="ranks",
    ...     gist="a plane of equilibria",
    ... )
    >>> decorator(lambda p: None)
    Traceback (most recent call last):
    ...
    ValueError: claim id 'spectrum.kernel' registered twice
    """
    if expected not in VERDICTS:
        raise ValueError(f"expected verdict of {id!r} must be one of {VERDICTS}; got {expected!r}")
    if source not in ("paper", "project"):
        raise ValueError(f"source of {id!r} must be 'paper' or 'project'; got {source!r}")
    if not paper_value or not paper_value.get("text"):
        raise ValueError(f"paper_value of {id!r} must state what the paper says, as 'text'")
    if not gist.strip():
        raise ValueError(f"gist of {id!r} must say in a few words what the check establishes")
    if not isinstance(decisive, str) or not decisive.strip():
        raise ValueError(
            f"decisive of {id!r} must name the reproduced value whose bound decides the verdict"
        )

    def wrap(fn: Callable[[dict[str, Any]], Outcome]) -> Callable[[dict[str, Any]], Outcome]:
        if id in _REGISTRY:
            raise ValueError(f"claim id {id!r} registered twice")
        _REGISTRY[id] = Claim(
            id, where, claim, paper_value, method, fn, expected, source, gist, decisive
        )
        return fn

    return wrap


def registered() -> Iterator[Claim]:
    """Yield the registered claims in registration order."""
    yield from _REGISTRY.values()


def decide(as_stated: bool, otherwise: Verdict = "failed") -> Verdict:
    """Return a claim's verdict by the one rule of the registry.

    ``confirmed`` when the paper's statement holds as stated, whatever the check finds
    beyond it: an addition (a sense of rotation, the sharpness of a bound, a rate the paper
    does not give) never makes a claim ``refined``. Otherwise ``otherwise``: ``refined``
    when only a narrower or more precise form holds (for some states, in one of the
    statement's readings), ``corrected`` when a corrected formula holds, ``undecidable``
    when the truth depends on values the paper does not give, ``failed`` when the numbers
    contradict it.

    Parameters
    ----------
    as_stated : bool
        Whether the paper's statement holds as stated.
    otherwise : str, optional
        The verdict when it does not: one of `VERDICTS` other than ``confirmed``.

    Returns
    -------
    str
        The verdict.

    Examples
    --------
    >>> decide(True, otherwise="refined")
    'confirmed'
    >>> decide(False, otherwise="refined")
    'refined'
    """
    if otherwise not in VERDICTS or otherwise == "confirmed":
        raise ValueError(f"otherwise must be a verdict other than 'confirmed'; got {otherwise!r}")
    return "confirmed" if as_stated else otherwise


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
