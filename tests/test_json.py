"""The JSON helpers of the package (`turntable._json`)."""

from __future__ import annotations

import math

import numpy as np

from turntable._json import finite_or_none, validator


def test_non_finite_floats_become_none_at_any_depth() -> None:
    value = {"a": math.nan, "b": [1.5, np.float64(math.inf), (2, "x")], "c": None}
    assert finite_or_none(value) == {"a": None, "b": [1.5, None, [2, "x"]], "c": None}
    assert type(finite_or_none(np.float64(0.25))) is float


def test_an_integer_is_an_int_and_a_number_may_be_asked_finite() -> None:
    schema = {"type": "object", "properties": {"n": {"type": "integer"}, "x": {"type": "number"}}}
    assert not validator(schema).is_valid({"n": 400.0})
    assert not validator(schema).is_valid({"n": True})
    assert validator(schema).is_valid({"n": 400, "x": math.inf})
    assert not validator(schema, finite_numbers=True).is_valid({"x": math.inf})
