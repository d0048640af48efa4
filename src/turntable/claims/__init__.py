"""The registry of the paper's claims and the checks that decide them.

Every claim of the paper (and a few the reproduction adds) is registered
once, with where it is in the paper, what the paper states, how it is
checked, and a check function that computes reproduced values with
`turntable`, compares them with independent references (high-precision
eigenvalues, the matrix exponential, symbolic algebra, the full
three-dimensional equations) and decides a verdict from the numbers
(`VERDICTS`, best to worst):

``confirmed``
    the claim holds as stated, whatever the check finds beyond it;
``refined``
    it does not hold as stated, but a narrower or more precise form does,
    stated in ``evidence``; a statement that holds under one reading of its
    words and fails under another is refined, the reading that holds being
    its precise form;
``corrected``
    a formula or a classification the paper prints is wrong, and ``evidence``
    states the right one (an erratum);
``undecidable``
    whether it holds depends on values the paper does not give (for instance
    experimental coefficients); never ``confirmed``;
``failed``
    the numbers contradict it.

One rule decides between them, `decide`: an addition beyond what the paper
states never makes a claim ``refined`` when the statement holds as stated.

The registry is the one source of the claims, of their order (the order of
registration, with the check modules imported in the paper's order, see
``CHECK_MODULES``) and of the verdict each is expected to reach (``expected=`` of
`register`); ``results/claims.json``, ``results/claims.md`` and the tests of
``tests/test_claims.py`` are generated from it.

Examples
--------
>>> from turntable import claims
>>> result = claims.evaluate("spectrum.kernel")
>>> result["verdict"]
'confirmed'
"""

from __future__ import annotations

import importlib
from collections.abc import Mapping
from typing import Any

from turntable.claims._core import (
    VERDICTS,
    Claim,
    Outcome,
    Quantity,
    Verdict,
    Where,
    clean,
    decide,
    register,
    registered,
)
from turntable.claims._params import DEFAULT_PARAMS, params_schema, resolve_params

#: The modules of checks, in the order of the paper; each registers its claims in that order.
CHECK_MODULES: tuple[str, ...] = (
    "_checks_intro",
    "_checks_model",
    "_checks_spectrum",
    "_checks_stability",
    "_checks_solution",
    "_checks_damping",
    "_checks_trajectory",
    "_checks_comparison",
    "_checks_limit",
    "_checks_realization",
)

for _name in CHECK_MODULES:
    importlib.import_module(f"{__name__}.{_name}")

_BY_ID: dict[str, Claim] = {c.id: c for c in registered()}

#: Claim identifiers in the order of the paper (the order of registration).
ORDER: tuple[str, ...] = tuple(_BY_ID)


def claim_ids() -> list[str]:
    """Return every claim id, in the order of the paper.

    Returns
    -------
    list of str
        The ids, as in `ORDER`.

    See Also
    --------
    get : The claim of an id.

    Examples
    --------
    >>> from turntable import claims
    >>> claims.claim_ids()[:3]
    ['intro.no_slip_motion', 'model.scaling', 'model.reduction']
    """
    return list(ORDER)


def get(claim_id: str) -> Claim:
    """Return the registered `Claim` with identifier ``claim_id``.

    Parameters
    ----------
    claim_id : str
        Identifier of the claim, one of `ORDER`.

    Returns
    -------
    Claim
        The claim.

    Raises
    ------
    ValueError
        If no claim has that identifier.

    Examples
    --------
    >>> from turntable import claims
    >>> claim = claims.get("solution.centre")
    >>> claim.where.label(), claim.decisive
    ('Sec. 2, (2.8)...', ...)
    """
    try:
        return _BY_ID[claim_id]
    except KeyError:
        raise ValueError(f"claim_id must be one of {list(ORDER)}; got {claim_id!r}") from None


def evaluate(claim_id: str, params: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """Run the check of one claim and return its record.

    Parameters
    ----------
    claim_id : str
        A registered identifier (see `claim_ids`).
    params : mapping, optional
        Check parameters over `DEFAULT_PARAMS` (see `resolve_params`).

    Returns
    -------
    dict
        ``id, source, where (section, equations, figure, label), claim,
        paper_value, method, reproduced, tolerance, summary, evidence,
        verdict, expected, gist, decisive, quantities``, with plain Python values and floats
        rounded to 12 significant digits.

    Raises
    ------
    RuntimeError
        If the check returns a verdict not in `VERDICTS`, no reproduced value under the
        claim's ``decisive`` key, or, with the expected verdict, no bound on it.

    See Also
    --------
    turntable.claims.evaluate_all : Every claim.
    turntable.claims.get : The claim itself.

    Examples
    --------
    >>> from turntable import claims
    >>> record = claims.evaluate("spectrum.kernel")
    >>> record["verdict"], record["decisive"]
    ('confirmed', 'ranks')
    """
    claim = get(claim_id)
    p = resolve_params(params)
    outcome = claim.check(p)
    if outcome.verdict not in VERDICTS:
        raise RuntimeError(f"check of {claim_id} returned verdict {outcome.verdict!r}")
    if claim.decisive not in outcome.reproduced or (
        outcome.verdict == claim.expected and claim.decisive not in outcome.tolerance
    ):
        raise RuntimeError(
            f"check of {claim_id} does not bound its decisive value {claim.decisive!r}: "
            "it must be a reproduced value and, when the check reaches its expected verdict, "
            f"a key of the tolerance ({sorted(outcome.tolerance)})"
        )
    return clean(
        {
            "id": claim.id,
            "source": claim.source,
            "where": {
                "section": claim.where.section,
                "equations": claim.where.equations,
                "figure": claim.where.figure,
                "label": claim.label(),
            },
            "claim": claim.claim,
            "paper_value": claim.paper_value,
            "method": claim.method,
            "reproduced": outcome.reproduced,
            "tolerance": outcome.tolerance,
            "summary": outcome.summary,
            "evidence": outcome.evidence,
            "verdict": outcome.verdict,
            "expected": claim.expected,
            "gist": claim.gist,
            "decisive": claim.decisive,
            "quantities": {key: q.record() for key, q in outcome.quantities.items()},
        }
    )


def evaluate_all(params: Mapping[str, Any] | None = None) -> list[dict[str, Any]]:
    """Run every check, in the order of the paper; see `evaluate`.

    Parameters
    ----------
    params : mapping, optional
        Parameters of the checks over `DEFAULT_PARAMS` (section ``claims`` of the
        configuration).

    Returns
    -------
    list of dict
        One record per claim, in the order of `ORDER` (see `evaluate`).

    See Also
    --------
    turntable.claims.evaluate : One claim.

    Examples
    --------
    On a coarser grid than the defaults, which the workflow uses:

    >>> from turntable import claims
    >>> records = claims.evaluate_all({"n_points": 31, "k_values": [0.4], "n_states": 1})
    >>> [r["id"] for r in records] == claims.claim_ids()
    True
    >>> [r["id"] for r in records if r["verdict"] == "failed"]
    []
    """
    p = resolve_params(params)
    return [evaluate(claim_id, p) for claim_id in ORDER]


__all__ = [
    "DEFAULT_PARAMS",
    "ORDER",
    "VERDICTS",
    "Claim",
    "Outcome",
    "Quantity",
    "Verdict",
    "Where",
    "claim_ids",
    "decide",
    "evaluate",
    "evaluate_all",
    "get",
    "params_schema",
    "register",
    "resolve_params",
]
