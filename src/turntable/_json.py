"""JSON helpers of the package: non-finite numbers as null, and a schema validator."""

from __future__ import annotations

import math
from typing import Any

import numpy as np


def finite_or_none(value: Any) -> Any:
    """Return ``value`` with every non-finite float replaced by None (JSON has no inf, NaN).

    Parameters
    ----------
    value : Any
        A float (numpy floats included), or a dict, list or tuple of such values, nested;
        anything else is returned as it is.

    Returns
    -------
    Any
        Floats as Python floats, or None where not finite; dicts with the same keys,
        lists and tuples as lists.
    """
    if isinstance(value, float | np.floating):
        x = float(value)
        return x if math.isfinite(x) else None
    if isinstance(value, dict):
        return {k: finite_or_none(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [finite_or_none(v) for v in value]
    return value


def _is_int(_checker: Any, value: Any) -> bool:
    # JSON Schema counts 400.0 as an integer; a count must be a Python int.
    return isinstance(value, int) and not isinstance(value, bool)


def _is_finite_number(_checker: Any, value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)


def validator_class(*, finite_numbers: bool = False) -> Any:
    """Return the JSON Schema (draft 2020-12) validator class for values read from YAML.

    Its ``integer`` is a Python int (not a bool, not a float such as 400.0, which JSON
    Schema itself counts as an integer); with ``finite_numbers``, its ``number`` refuses inf
    and NaN.
    """
    import jsonschema

    base = jsonschema.Draft202012Validator
    types = {"integer": _is_int} | ({"number": _is_finite_number} if finite_numbers else {})
    return jsonschema.validators.extend(base, type_checker=base.TYPE_CHECKER.redefine_many(types))


def validator(schema: dict[str, Any], *, finite_numbers: bool = False) -> Any:
    """Return a validator of ``schema`` of `validator_class`."""
    return validator_class(finite_numbers=finite_numbers)(schema)
