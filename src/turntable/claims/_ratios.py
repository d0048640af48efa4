"""How much faster one spiral untwists than another: the ratios of the two mechanisms' growth,
the verdict of "much faster" by a factor, and where a ratio crosses a level."""

from __future__ import annotations

import itertools
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

import turntable as tt
from turntable import rolling
from turntable.claims._core import Verdict

#: The matching the verdict rests on: equal mean dissipated power on the same path of the
#: centre, each ball with its own kinematics (the only one tied to a motion both balls make).
BASIS = "equal_power"

#: The matchings of the coefficients compared: BASIS, and equal coefficients (delta = mu0) as
#: a sensitivity (equal numbers in the units of the model, tied to no motion). The equal-decay
#: matching of `turntable.rolling` is left out: it equates the rolling ball's slow drift of its
#: centre with the slipping ball's fast transient.
COMPARISONS = (BASIS, "equal_coefficient")


def growth_ratios(coefficient: Any, k: float) -> dict[str, NDArray[np.float64]]:
    """`rolling.growth_per_turn_ratio` under each of `COMPARISONS`."""
    return {name: rolling.growth_per_turn_ratio(coefficient, k, name) for name in COMPARISONS}


def rate_ratios(coefficient: Any, k: float) -> dict[str, NDArray[np.float64]]:
    """The growth rate per unit time of the slipping spiral, alpha1 (2.5), over the rolling
    one's, Re lambda_g at the matched delta, under each of `COMPARISONS`."""
    alpha1 = tt.spectrum(coefficient, k).alpha1
    return {
        name: alpha1 / rolling.growth_rate(rolling.matched_delta(coefficient, k, name), k)
        for name in COMPARISONS
    }


def much_faster_verdict(ratios: Mapping[Any, ArrayLike], factor: float) -> Verdict:
    """Decide "with slipping the spiral untwists much faster" from ratios slipping/rolling.

    Parameters
    ----------
    ratios : mapping
        For each comparison and measure, the ratio slipping over rolling of how fast the
        spiral untwists, at every coefficient tried (arrays of numbers > 0).
    factor : float
        What "much faster" means: faster by at least this factor (> 1).

    Returns
    -------
    str
        ``"confirmed"`` if slipping is much faster under every comparison, measure and
        coefficient (every ratio >= factor); ``"failed"`` if neither mechanism is ever
        much faster (every ratio strictly between 1 / factor and factor), so that the
        statement fails under either reading of the paper's "in this case";
        ``"undecidable"`` otherwise: which mechanism is much faster, or whether one is,
        depends on the comparison, the measure or the coefficient, none of which the
        paper fixes.
    """
    if not factor > 1.0:
        raise ValueError(f"factor must be > 1; got {factor!r}")
    values = np.concatenate([np.ravel(np.asarray(r, dtype=float)) for r in ratios.values()])
    if values.size == 0 or not np.all(np.isfinite(values) & (values > 0)):
        raise ValueError("ratios must be finite numbers > 0, at least one")
    if np.all(values >= factor):
        return "confirmed"
    if np.all((values > 1.0 / factor) & (values < factor)):
        return "failed"
    return "undecidable"


def factors_with_the_same_verdict(
    smallest: float, largest: float, factor: float
) -> list[float | None]:
    """Return [low, high]: the factors F in low < F <= high give the verdict ``factor`` gives.

    Parameters
    ----------
    smallest, largest : float
        The smallest and the largest ratio slipping over rolling (> 0).
    factor : float
        The factor of `much_faster_verdict` (> 1).

    Returns
    -------
    list
        [low, high], high None when the range has no upper end.

    Notes
    -----
    For F > 1, `much_faster_verdict` is confirmed iff smallest >= F, failed iff
    F > largest and F > 1 / smallest, undecidable otherwise.  With smallest > 1:
    confirmed on (1, smallest], undecidable on (smallest, largest], failed above.  With
    smallest <= 1: undecidable on (1, max(largest, 1 / smallest)], failed above.
    """
    edges = [1.0, smallest, largest] if smallest > 1.0 else [1.0, max(largest, 1.0 / smallest)]
    for low, high in itertools.pairwise(edges):
        if low < factor <= high:
            return [low, high]
    return [edges[-1], None]


def _crossover(
    ratios: Callable[[Any, float], dict[str, Any]],
    name: str,
    grid: NDArray[np.float64],
    ratio: NDArray[np.float64],
    k: float,
    level: float,
) -> float | None:
    """The coefficient at which ``ratios(mu0, k)[name]`` crosses ``level`` (None unless
    exactly once on the grid), refined by Brent's method in log mu0."""
    # within 1e-9 of the level counts as on it: no crossing found in rounding noise
    side = np.where(np.abs(ratio / level - 1.0) < 1e-9, 0.0, np.sign(ratio - level))
    idx = np.flatnonzero(side[:-1] * side[1:] < 0)
    if idx.size != 1:
        return None
    i = int(idx[0])

    from scipy.optimize import brentq

    def f(lm: float) -> float:
        return float(ratios(10.0**lm, k)[name]) / level - 1.0

    return float(10.0 ** brentq(f, np.log10(grid[i]), np.log10(grid[i + 1]), xtol=1e-14))


def _order(x: tuple[float, float], y: tuple[float, float]) -> float:
    """The exponent p of y ~ x^p through two points."""
    return float(np.log(y[0] / y[1]) / np.log(x[0] / x[1]))
