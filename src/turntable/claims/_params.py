"""The parameters of the claims checks: their schema and defaults, and what they define (the
grid of mu0, the random states)."""

from __future__ import annotations

import functools
from collections.abc import Mapping
from importlib import resources
from types import MappingProxyType
from typing import Any

import numpy as np
import yaml
from numpy.typing import NDArray

from turntable._json import validator

#: The JSON schema of the check parameters (package data): the one source of their
#: defaults and of their validation; the workflow's configuration schema refers to it.
PARAMS_SCHEMA_FILE = "params.schema.yaml"


@functools.cache
def params_schema() -> dict[str, Any]:
    """Return the JSON schema of the check parameters, read from the package data."""
    text = resources.files("turntable.claims").joinpath(PARAMS_SCHEMA_FILE).read_text("utf-8")
    schema: dict[str, Any] = yaml.safe_load(text)
    return schema


def _defaults() -> dict[str, Any]:
    return {key: prop["default"] for key, prop in params_schema()["properties"].items()}


#: Parameters of the checks with the values used when a key is not given: the ``default``
#: of each property of the schema (read-only view; edit the schema to change one).
DEFAULT_PARAMS: Mapping[str, Any] = MappingProxyType(_defaults())


def _property_type(prop: Mapping[str, Any]) -> str:
    ref = prop.get("$ref", "")
    if "type" not in prop and ref.startswith("#/$defs/"):
        return _property_type(params_schema()["$defs"][ref.removeprefix("#/$defs/")])
    return str(prop.get("type", ""))


def _as_float(value: Any) -> Any:
    if isinstance(value, (list, tuple)):
        return [_as_float(v) for v in value]
    return float(value)


def resolve_params(params: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """Return the check parameters: ``params`` over `DEFAULT_PARAMS`, validated.

    The defaults and the rules (types, bounds, lengths) are those of the JSON schema
    ``params.schema.yaml`` of this package (see ``params_schema``), the same the workflow
    validates the ``claims:`` section of the workflow's configuration against; an integer must
    be an ``int`` (not ``400.0``). The one rule a schema cannot express is added here:
    ``mu0_range`` is increasing. (That ``state_si`` is not all zero is the schema's.)

    Parameters
    ----------
    params : mapping, optional
        Any subset of the keys of `DEFAULT_PARAMS` (for instance the
        ``claims:`` section of the workflow's configuration).

    Returns
    -------
    dict
        Every key of `DEFAULT_PARAMS`; numbers as floats, counts as ints.

    Raises
    ------
    ValueError
        For an unknown key or a value of the wrong type or range; the message
        names the key and what the schema expects.

    Examples
    --------
    >>> from turntable import claims
    >>> claims.resolve_params({"k_paper": 0.5})["k_paper"]
    0.5
    >>> claims.resolve_params({"n_points": 400.0})
    Traceback (most recent call last):
    ...
    ValueError: params['n_points']: 400.0 is not of type 'integer' (expected: ...)
    """
    p = {**_defaults(), **dict(params or {})}
    schema = params_schema()
    errors = sorted(validator(schema).iter_errors(p), key=lambda e: list(e.absolute_path))
    if errors:
        err = errors[0]
        path = "".join(f"[{x!r}]" for x in err.absolute_path) or ""
        if err.validator == "additionalProperties":
            known = sorted(schema["properties"])
            raise ValueError(f"unknown claims parameter(s): {err.message}; known: {known}")
        described = schema["properties"].get(err.absolute_path[0], {}).get("description", "")
        # jsonschema words a `not` as "... should not be valid under {schema}": the
        # description says what is wanted (e.g. state_si: "not all zero")
        message = f"{err.instance!r} is not allowed" if err.validator == "not" else err.message
        raise ValueError(f"params{path}: {message} (expected: {' '.join(described.split())})")
    low, high = p["mu0_range"]
    if not low < high:
        raise ValueError(
            f"params['mu0_range'] must be [low, high] with low < high; got {low, high}"
        )
    return {
        key: (value if _property_type(schema["properties"][key]) == "integer" else _as_float(value))
        for key, value in p.items()
    }


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
