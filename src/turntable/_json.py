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


def validator(schema: dict[str, Any], *, finite_numbers: bool = False) -> Any:
    """Return a JSON Schema (draft 2020-12) validator of ``schema`` for values read from YAML.

    Parameters
    ----------
    schema : dict
        The schema.
    finite_numbers : bool
        Also refuse inf and NaN where the schema asks for a ``number``.

    Returns
    -------
    jsonschema.protocols.Validator
        A validator whose ``integer`` is a Python int (not a bool, not a float such as
        400.0, which JSON Schema itself counts as an integer).
    """
    import jsonschema

    base = jsonschema.Draft202012Validator
    types = {"integer": _is_int} | ({"number": _is_finite_number} if finite_numbers else {})
    cls = jsonschema.validators.extend(base, type_checker=base.TYPE_CHECKER.redefine_many(types))
    return cls(schema)
