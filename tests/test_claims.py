"""The claims registry: one test per registered claim, plus the registry's own guarantees.

The tests are generated from the registry: each claim is checked with the parameters of
the ``claims:`` section of the workflow's configuration (the same the workflow uses for
results/claims.json), and a verdict other than the one its registration expects
(``expected=`` of `turntable.claims.register`) fails the suite.  Further tests break the
model on purpose and require the affected check to notice.
"""

from __future__ import annotations

import functools
import importlib
import json
import math
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import mpmath
import numpy as np
import pytest
import scipy.linalg
import yaml

import turntable
from ci_build import full_config
from turntable import claims
from turntable.claims import report
from turntable.claims._core import split_bound, within
from turntable.claims._params import mu0_grid

ROOT = Path(__file__).resolve().parents[1]

FIELDS = {
    "id",
    "source",
    "where",
    "claim",
    "paper_value",
    "method",
    "reproduced",
    "tolerance",
    "summary",
    "evidence",
    "verdict",
    "expected",
    "gist",
    "decisive",
    "quantities",
}


@functools.cache
def config_params() -> dict[str, Any]:
    """The ``claims:`` section of the workflow's configuration, defaults filled in."""
    return full_config()["claims"]


def _evaluate(claim_id: str) -> dict[str, Any]:
    return claims.evaluate(claim_id, config_params())


@pytest.fixture(scope="session")
def evaluated_all(computed: Any) -> Callable[[], dict[str, dict[str, Any]]]:
    """Every claim evaluated with the workflow's parameters, once per test run (shared by
    the xdist workers, which split the work between them)."""
    return functools.cache(lambda: computed("claims", claims.claim_ids(), _evaluate))


@pytest.fixture(scope="session")
def evaluated(computed: Any) -> Callable[[str], dict[str, Any]]:
    """One claim evaluated with the workflow's parameters, once per test run."""
    return functools.cache(lambda claim_id: computed("claims", [claim_id], _evaluate)[claim_id])


def _numbers(value: Any) -> list[float]:
    """Every int or float (not bool) anywhere inside ``value``."""
    if isinstance(value, dict):
        return [x for v in value.values() for x in _numbers(v)]
    if isinstance(value, list):
        return [x for v in value for x in _numbers(v)]
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return [float(value)]
    return []


@pytest.mark.parametrize("claim_id", claims.claim_ids(), ids=claims.claim_ids())
def test_claim_has_its_expected_verdict(claim_id: str, evaluated: Callable) -> None:
    result = evaluated(claim_id)
    assert set(result) == FIELDS
    assert result["id"] == claim_id
    assert result["verdict"] in claims.VERDICTS
    numbers = _numbers(result["reproduced"])
    assert numbers, f"{claim_id}: the check produced no numbers"
    assert all(math.isfinite(x) for x in numbers)
    assert result["summary"]
    assert result["evidence"]
    assert result["method"]
    assert result["verdict"] != "failed", f"{claim_id} failed: {result['evidence']}"
    expected = claims.get(claim_id).expected
    assert result["verdict"] == expected, f"{claim_id}: {result['evidence']}"
    # Every bound is stated under the key of the reproduced value it bounds.
    assert set(result["tolerance"]) <= set(result["reproduced"]), claim_id
    # The bounds are those the verdict rests on, and each holds: what makes a verdict
    # refined, corrected or undecidable is stated as a bound that is met, never as one
    # that is broken (only a failed verdict shows a broken bound).
    unmet = {
        key: (result["reproduced"][key], bound)
        for key, bound in result["tolerance"].items()
        if not within(result["reproduced"][key], bound)
    }
    assert unmet == {}, f"{claim_id}: bounds not met by a {result['verdict']} verdict"


def test_verdicts_best_to_worst() -> None:
    assert claims.VERDICTS == ("confirmed", "refined", "corrected", "undecidable", "failed")
    assert set(report.VERDICT_MEANINGS) == set(claims.VERDICTS)


def test_order_is_the_order_of_registration() -> None:
    ids = claims.claim_ids()
    assert ids == [c.id for c in claims.registered()]
    assert len(set(ids)) == len(ids)
    # The paper's sections come in the paper's order.
    first = {
        prefix: ids.index(next(i for i in ids if i.startswith(prefix)))
        for prefix in ("model.", "spectrum.", "solution.", "limit.")
    }
    assert first["model."] < first["spectrum."] < first["solution."] < first["limit."]


def test_every_claim_records_where_it_is_and_what_the_paper_says() -> None:
    for claim_id in claims.claim_ids():
        c = claims.get(claim_id)
        assert c.where.section, claim_id
        assert c.claim.endswith("."), claim_id
        assert c.paper_value.get("text"), claim_id
        assert c.source in ("paper", "project"), claim_id
        assert c.expected in claims.VERDICTS, claim_id
        # An addition of the reproduction never reads as a location of the paper.
        assert (c.source == "project") == c.label().startswith("addition (from ")


def test_registration_refuses_a_claim_without_expected_verdict_or_paper_value() -> None:
    where = claims.Where("Sec. 0")
    base = {"where": where, "claim": "c.", "method": "m", "gist": "g", "decisive": "a"}
    with pytest.raises(ValueError, match="expected verdict"):
        claims.register("x.y", **base, paper_value={"text": "t"}, expected="probably")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="paper_value"):
        claims.register("x.y", **base, paper_value={}, expected="confirmed")
    with pytest.raises(ValueError, match="gist"):
        claims.register(
            "x.y", **{**base, "gist": " "}, paper_value={"text": "t"}, expected="confirmed"
        )
    with pytest.raises(ValueError, match="decisive"):
        claims.register(
            "x.y", **{**base, "decisive": ""}, paper_value={"text": "t"}, expected="confirmed"
        )
    without = {key: value for key, value in base.items() if key != "decisive"}
    with pytest.raises(TypeError, match="decisive"):
        claims.register("x.y", **without, paper_value={"text": "t"}, expected="confirmed")  # type: ignore[call-arg]
    with pytest.raises(ValueError, match="tolerance keys without a reproduced value"):
        claims.Outcome("confirmed", {"a": 1.0}, {"b": 1.0}, "s", "e")


@pytest.mark.parametrize("claim_id", claims.claim_ids(), ids=claims.claim_ids())
def test_every_claim_names_the_value_that_decides_it(claim_id: str, evaluated: Callable) -> None:
    """The registry names, for each claim, one reproduced value whose bound decides the
    verdict; it has a bound in the tolerance, and the bound holds."""
    result = evaluated(claim_id)
    key = claims.get(claim_id).decisive
    assert result["decisive"] == key
    assert key in result["reproduced"]
    assert key in result["tolerance"]
    assert within(result["reproduced"][key], result["tolerance"][key])


def test_a_check_that_does_not_bound_its_decisive_value_is_refused(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    import dataclasses

    claim = claims.get("spectrum.kernel")
    wrong = dataclasses.replace(claim, decisive="not_a_reproduced_value")
    monkeypatch.setitem(claims._BY_ID, "spectrum.kernel", wrong)
    with pytest.raises(RuntimeError, match="not_a_reproduced_value"):
        claims.evaluate("spectrum.kernel")


def test_unknown_claim_id_names_the_argument() -> None:
    with pytest.raises(ValueError, match="claim_id"):
        claims.evaluate("spectrum.nonexistent")


@pytest.mark.parametrize(
    ("key", "value"),
    [
        ("k_values", [0.4, -1.0]),
        ("k_paper", "2/5"),
        ("mu0_range", [1.0, 0.5]),
        ("n_points", 3),
        ("state_fig4", [1.0, 1.0, 0.0]),
        ("mu0_small", [1.0e-6, 0.5]),
        ("seed", True),
        ("n_points", 400.0),
        ("turntable_rpm", [33.0]),
        ("turntable_rpm", [33.0, 33.0]),
        ("state_si", [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
        ("ball_radius", -0.01),
        ("no_such_key", 1),
    ],
)
def test_bad_params_raise_naming_the_key(key: str, value: Any) -> None:
    with pytest.raises(ValueError, match=key):
        claims.resolve_params({key: value})


@pytest.mark.parametrize("state", [[0.0] * 6, [0, 0, 0, 0, 0, -0.0]])
def test_an_all_zero_scaling_state_is_refused_by_the_schema_in_words(state: list) -> None:
    """The schema's `not: {items: {const: 0}}` is the one check (no second one in code), and
    its message says what is wrong and what is expected, not the schema's own text."""
    with pytest.raises(ValueError, match="state_si") as info:
        claims.resolve_params({"state_si": state})
    message = str(info.value)
    assert message.startswith(f"params['state_si']: {state!r} is not allowed (expected: ")
    assert "not all zero" in message
    assert "should not be valid" not in message
    assert "const" not in message
    assert len(message.splitlines()) == 1


def test_the_schema_is_the_one_source_of_defaults_and_rules() -> None:
    """The package's schema gives every default; the workflow's schema refers to it."""
    schema = claims.params_schema()
    assert set(schema["properties"]) == set(claims.DEFAULT_PARAMS)
    assert "required" not in schema  # a key left out takes its default
    for key, prop in schema["properties"].items():
        assert prop.get("description"), key
        assert "default" in prop, key
        assert claims.DEFAULT_PARAMS[key] == prop["default"], key
    with open(ROOT / "workflow" / "schemas" / "config.schema.yaml", encoding="utf-8") as fh:
        workflow_schema = yaml.safe_load(fh)["properties"]["claims"]
    target = (ROOT / "workflow" / "schemas" / workflow_schema["$ref"]).resolve()
    assert target == (ROOT / "src/turntable/claims" / "params.schema.yaml").resolve()
    assert claims.resolve_params(config_params()) == claims.resolve_params(claims.DEFAULT_PARAMS)
    assert claims.resolve_params({}) == claims.resolve_params(claims.DEFAULT_PARAMS)


# A wrong model must not pass -------------------------------------------------------------

#: Fewer points than the configuration, to keep the deliberately broken runs short.
SMALL = {
    "k_values": [0.4, 1.0],
    "mu0_probe": [0.1, 10.0],
    "mu0_reference": [0.1, 1.0],
    "mu0_limit": [10.0, 100.0, 1000.0],
    "n_states": 2,
}


def test_printed_sign_of_the_centre_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    def printed(z0: Any, k: float) -> np.ndarray:
        z0 = np.asarray(z0, dtype=float)
        return np.array([(k * z0[4] - z0[3]) / k, (k * z0[5] - z0[2]) / k])

    monkeypatch.setattr(turntable, "spiral_centre", printed)
    assert claims.evaluate("solution.centre", SMALL)["verdict"] == "failed"


def test_perturbed_spectrum_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    exact = turntable.spectrum

    def perturbed(mu0: Any, k: Any) -> turntable.Spectrum:
        s = exact(mu0, k)
        return s._replace(alpha1=s.alpha1 * (1 + 1e-9))

    monkeypatch.setattr(turntable, "spectrum", perturbed)
    assert claims.evaluate("spectrum.roots", SMALL)["verdict"] == "failed"


def test_wrong_sign_of_the_friction_torque_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    exact = turntable.system_matrix

    def wrong(mu0: float, k: float) -> np.ndarray:
        big = exact(mu0, k).copy()
        big[4:, 2:4] *= -1.0  # gamma x v enters the spin equation with the wrong sign
        return big

    monkeypatch.setattr(turntable, "system_matrix", wrong)
    params = SMALL
    assert claims.evaluate("model.reduction", params)["verdict"] == "failed"
    assert claims.evaluate("spectrum.char_poly", params)["verdict"] == "failed"


def test_wrong_scale_of_the_damping_ratio_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    exact = turntable.log_damping_ratio

    def scaled(mu0: Any, k: Any) -> Any:
        return exact(mu0, k) * (1 + 1e-6)  # ln N off by a relative 1e-6, bound still holds

    monkeypatch.setattr(turntable, "log_damping_ratio", scaled)
    assert claims.evaluate("solution.damping_ratio", SMALL)["verdict"] == "failed"


def test_wrong_sign_of_the_beta_remainder_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    from turntable import reference as ref

    exact = ref.mp_spectrum

    def flipped(mu0: float, k: float) -> ref.MpSpectrum:
        # Mirror the imaginary parts about k/(k+1): same |remainder|, opposite sign.
        e = exact(mu0, k)
        with mpmath.workdps(ref.DPS):
            kk = mpmath.mpf(k) / (mpmath.mpf(k) + 1)
            roots = tuple(
                mpmath.mpc(z.real, mpmath.sign(z.imag) * (2 * kk - abs(z.imag))) for z in e.roots
            )
        return e._replace(roots=roots)

    monkeypatch.setattr(ref, "mp_spectrum", flipped)
    assert claims.evaluate("limit.expansion", SMALL)["verdict"] == "failed"


def test_wrong_no_slip_rate_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    def wrong(z0: Any, t: Any, k: float) -> np.ndarray:
        z = np.asarray(z0, dtype=float)
        rc = complex(*turntable.spiral_centre(z, k))
        rho = (complex(z[0], z[1]) - rc) * np.exp(1j * k / (k + 2.0) * np.asarray(t))
        v = 1j * k / (k + 2.0) * rho
        w = rc + rho / (k + 1.0)
        return np.column_stack([(rc + rho).real, (rc + rho).imag, v.real, v.imag, w.real, w.imag])

    monkeypatch.setattr(turntable, "nonholonomic", wrong)
    params = SMALL
    assert claims.evaluate("limit.frequency", params)["verdict"] == "failed"
    assert claims.evaluate("limit.convergence", params)["verdict"] == "failed"
    assert claims.evaluate("intro.no_slip_motion", params)["verdict"] == "failed"


def test_wrong_contact_force_of_rolling_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    """A no-slip reference built with the inertia ratio off by half."""
    from turntable.claims import _constrained as con

    exact = con.no_slip_matrix

    def wrong(k: float) -> np.ndarray:
        return exact(1.5 * k)

    monkeypatch.setattr(con, "no_slip_matrix", wrong)
    assert claims.evaluate("intro.no_slip_motion", SMALL)["verdict"] == "failed"
    assert claims.evaluate("limit.realization", SMALL)["verdict"] == "failed"


def test_rolling_without_contact_force_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    """The motion on u = 0 without the force that keeps it there is not the limit."""
    from turntable.claims import _constrained as con

    def free(k: float) -> np.ndarray:
        big = np.zeros((6, 6))
        big[0:2, 2:4] = np.eye(2)
        return big

    monkeypatch.setattr(con, "no_slip_matrix", free)
    assert claims.evaluate("limit.realization", SMALL)["verdict"] == "failed"


def test_orthogonal_projection_is_not_the_state_after_the_layer(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    from turntable.claims import _constrained as con

    def orthogonal(k: float) -> np.ndarray:
        basis = scipy.linalg.null_space(con.slip_matrix())
        return basis @ basis.T

    monkeypatch.setattr(con, "no_slip_projection", orthogonal)
    assert claims.evaluate("limit.realization", SMALL)["verdict"] == "failed"


@pytest.mark.parametrize(
    "wrong",
    [
        pytest.param(lambda c, m, om: c / m, id="without-Omega"),
        pytest.param(lambda c, m, om: c / (m * om**2), id="Omega-squared"),
        pytest.param(lambda c, m, om: 1.01 * c / (m * om), id="one-percent-off"),
    ],
)
def test_wrong_friction_scaling_fails(monkeypatch: pytest.MonkeyPatch, wrong: Any) -> None:
    from turntable.claims import _checks_intro

    monkeypatch.setattr(_checks_intro, "dimensionless_friction", wrong)
    assert claims.evaluate("model.scaling", SMALL)["verdict"] == "failed"


def test_a_plane_that_slips_less_when_faster_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    """model.scaling tests the paper's "slipping on a fast rotating plane": a friction that
    grows like Omega^2, in both the dimensional model and mu0 (so that the conversion of
    units still agrees), makes mu0 grow with the plane's rate and the ball slip less on the
    faster plane, and the check must fail on that alone."""
    from turntable.claims import _checks_intro

    exact_matrix = _checks_intro.dimensional_matrix
    reference_rate = _checks_intro.plane_rate(33.0)

    def friction(c: float, omega: float) -> float:
        return c * (omega / reference_rate) ** 2

    monkeypatch.setattr(
        _checks_intro,
        "dimensional_matrix",
        lambda c, m, i, r, om: exact_matrix(friction(c, om), m, i, r, om),
    )
    monkeypatch.setattr(
        _checks_intro, "dimensionless_friction", lambda c, m, om: friction(c, om) / (m * om)
    )
    result = claims.evaluate("model.scaling", SMALL)
    assert result["reproduced"]["scaling_error_rel"] < 1e-9  # the conversion still agrees
    assert result["reproduced"]["persistent_slip_fast_over_slow"] < 1.0
    assert result["verdict"] == "failed"


def test_wrong_torque_arm_of_the_dimensional_model_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    from turntable.claims import _checks_intro

    exact = _checks_intro.dimensional_matrix

    def wrong(friction: float, mass: float, inertia: float, radius: float, omega: float):
        return exact(friction, mass, inertia * 1.1, radius, omega)  # torque arm off by 10 %

    monkeypatch.setattr(_checks_intro, "dimensional_matrix", wrong)
    assert claims.evaluate("model.scaling", SMALL)["verdict"] == "failed"


@pytest.mark.parametrize(
    ("rate", "error"),
    [
        pytest.param("alpha1", 1e-5, id="alpha1-alone-off-1e-5"),
        pytest.param("beta", 3e-9, id="beta-alone-off-3e-9"),
    ],
)
def test_spiral_with_a_wrong_rate_fails(
    monkeypatch: pytest.MonkeyPatch, rate: str, error: float
) -> None:
    """Predicted alpha1 alone or beta alone off by a small relative error: the fit of that
    rate must notice, each with its own bound (1e-6 on the growth rate, 1e-9 on the
    angular rate), so that loosening either bound alone is caught."""
    from turntable import reference as ref

    exact = ref.float_spectrum

    def off(matrix: np.ndarray) -> ref.MpSpectrum:
        e = exact(matrix)
        return e._replace(**{rate: getattr(e, rate) * (1 + error)})

    monkeypatch.setattr(ref, "float_spectrum", off)
    assert claims.evaluate("trajectory.spiral", SMALL)["verdict"] == "failed"


def test_spiral_about_a_misplaced_centre_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    """A spiral centre 1e-3 away from (x0, y0) makes the distance oscillate: not a log spiral."""
    from turntable import reference as ref

    exact = ref.kernel_projection

    def shifted(matrix: np.ndarray, z0: Any) -> np.ndarray:
        return exact(matrix, z0) + np.array([1e-3, 0.0])

    monkeypatch.setattr(ref, "kernel_projection", shifted)
    assert claims.evaluate("trajectory.spiral", SMALL)["verdict"] == "failed"


def test_inward_spiral_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    """A spiral winding in at rate alpha1 (the radius times exp(-2 alpha1 t)) must fail."""
    from turntable import reference as ref

    exact = ref.expm_solution

    def inward(matrix: np.ndarray, z0: Any, t: Any) -> np.ndarray:
        z = exact(matrix, z0, t)
        rc = ref.kernel_projection(matrix, z0)
        shrink = np.exp(-2.0 * ref.float_spectrum(matrix).alpha1 * np.asarray(t))
        z[:, :2] = rc + (z[:, :2] - rc) * shrink[:, None]
        return z

    monkeypatch.setattr(ref, "expm_solution", inward)
    assert claims.evaluate("trajectory.spiral", SMALL)["verdict"] == "failed"


def test_vertical_spin_fed_into_the_slip_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    """The rubber-ball identity is not vacuous: a slip that depends on wz is noticed.

    The mistake: the contact point's velocity taken from the whole position vector of the
    centre, w x (-r), instead of w x (-R gamma); then wz enters the planar motion.
    """
    from turntable.claims import _checks_model as checks

    ne = importlib.import_module("turntable.newton_euler")

    def wrong(r: np.ndarray, v: np.ndarray, w: np.ndarray) -> np.ndarray:
        return v + np.cross(w, -r) - np.cross(ne.GAMMA, r)

    checks._newton_euler.cache_clear()
    monkeypatch.setattr(ne, "_slip", wrong)
    try:
        assert claims.evaluate("model.rubber_ball", SMALL)["verdict"] == "failed"
    finally:
        checks._newton_euler.cache_clear()


def test_dimensional_spin_holds_for_another_ball(monkeypatch: pytest.MonkeyPatch) -> None:
    from turntable.claims import _checks_spectrum as checks

    monkeypatch.setattr(checks, "DIMENSIONAL_BALL", {"R": 2.0, "Omega": 0.3, "m": 5.0})
    result = claims.evaluate("spectrum.kernel", SMALL)
    assert result["verdict"] == "confirmed"
    assert result["reproduced"]["dimensional_ball"]["R"] == 2.0


def test_wrong_dimensional_spin_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    """Equations whose plane turns 1% faster than the Omega of the statement must fail."""
    from turntable.claims import _checks_spectrum as checks

    exact = checks._dimensional_matrix

    def faster(mu0_dim: float, k: float, ball: dict[str, float]) -> np.ndarray:
        return exact(mu0_dim, k, {**ball, "Omega": 1.01 * ball["Omega"]})

    monkeypatch.setattr(checks, "_dimensional_matrix", faster)
    assert claims.evaluate("spectrum.kernel", SMALL)["verdict"] == "failed"


#: The wrong models below break a statement at a few points of the mu0 grid only, in a
#: window away from every probe, reference and small mu0 of SMALL, so that only the check
#: of the statement on the grid can notice.  The grid of SMALL runs over 1e-6..1e6 (20
#: points a decade); for the damping bound it is extended down to 1e-12, below every small
#: mu0, since ln N increases with mu0 and can only fall below 2 pi at the low end.
MIDDLE = (2.0, 5.0)
LOWEST = (0.0, 1e-11)
SMALL_FROM_1E_12 = {**SMALL, "mu0_range": [1e-12, 1e6]}


def _in(window: tuple[float, float], mu0: Any) -> np.ndarray:
    mu0 = np.asarray(mu0, dtype=float)
    return (mu0 > window[0]) & (mu0 < window[1])


def _alpha1_negative_somewhere(exact: Any) -> Any:
    """`turntable.spectrum` with alpha1 of the opposite sign (> -1) for mu0 in MIDDLE."""

    def wrong(mu0: Any, k: Any) -> turntable.Spectrum:
        s = exact(mu0, k)
        return s._replace(alpha1=np.where(_in(MIDDLE, mu0), -s.alpha1, s.alpha1))

    return wrong


def _per_turn_rising_somewhere(exact: Any) -> Any:
    """`turntable.log_growth_per_turn` doubled for mu0 in MIDDLE: it rises on entering it."""

    def wrong(mu0: Any, k: Any) -> np.ndarray:
        return np.where(_in(MIDDLE, mu0), 2.0 * exact(mu0, k), exact(mu0, k))

    return wrong


def _ratio_below_one_somewhere(exact: Any) -> Any:
    """`turntable.log_damping_ratio` less pi/2 for mu0 in LOWEST: |alpha2|/beta = 3/4 + o(1)
    there, and ln N still increases with mu0 (it jumps up by pi/2 on leaving LOWEST)."""

    def wrong(mu0: Any, k: Any) -> np.ndarray:
        return exact(mu0, k) - np.where(_in(LOWEST, mu0), 0.5 * np.pi, 0.0)

    return wrong


@pytest.mark.parametrize(
    ("claim_id", "name", "wrong", "window", "params"),
    [
        pytest.param(
            "spectrum.unstable_focus",
            "spectrum",
            _alpha1_negative_somewhere,
            MIDDLE,
            SMALL,
            id="unstable_focus-alpha1-negative-somewhere",
        ),
        pytest.param(
            "trajectory.untwisting_slows",
            "log_growth_per_turn",
            _per_turn_rising_somewhere,
            MIDDLE,
            SMALL,
            id="untwisting_slows-per-turn-rising-somewhere",
        ),
        pytest.param(
            "solution.damping_ratio",
            "log_damping_ratio",
            _ratio_below_one_somewhere,
            LOWEST,
            SMALL_FROM_1E_12,
            id="damping_ratio-ratio-below-1-somewhere",
        ),
    ],
)
def test_statement_broken_somewhere_fails(
    monkeypatch: pytest.MonkeyPatch,
    claim_id: str,
    name: str,
    wrong: Any,
    window: tuple[float, float],
    params: dict[str, Any],
) -> None:
    """A model that breaks the statement at a few grid points only, and only slightly
    (alpha1 > -1, per-turn growth rising once, |alpha2|/beta > 1/2): the check must notice,
    so it holds the statement everywhere on the grid and with the paper's strict bound."""
    resolved = claims.resolve_params(params)
    assert np.any(_in(window, mu0_grid(resolved)))
    for key in ("mu0_probe", "mu0_reference", "mu0_small"):
        assert not np.any(_in(window, resolved[key])), key
    monkeypatch.setattr(turntable, name, wrong(getattr(turntable, name)))
    assert claims.evaluate(claim_id, params)["verdict"] == "failed"


def test_decaying_part_turning_with_the_plane_is_not_refined(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Mirror the decaying part so that it turns like the growing one: the check notices."""
    exact = turntable.modal_terms

    def mirrored(z0: Any, t: Any, mu0: float, k: float) -> Any:
        m = exact(z0, t, mu0, k)
        minus = m.minus * np.array([1.0, -1.0, 1.0, -1.0, 1.0, -1.0])
        return m._replace(minus=minus)

    monkeypatch.setattr(turntable, "modal_terms", mirrored)
    assert claims.evaluate("solution.decomposition", SMALL)["verdict"] == "failed"


def test_a_zero_failed_summary_names_the_erratum() -> None:
    records = [
        {"id": "a.b", "verdict": "confirmed", "source": "paper"},
        {"id": "c.d", "verdict": "corrected", "source": "paper"},
        {"id": "e.f", "verdict": "refined", "source": "project"},
    ]
    summary = report.summarize(records)
    line = report.summary_line(summary)
    assert "0 failed" in line
    assert "1 corrected" in line
    assert "Corrected: `c.d`" in line
    # The paper's claims are counted apart from the additions.
    assert (
        "Of the 2 of the paper: 1 confirmed, 0 refined, 1 corrected, 0 undecidable, 0 failed; "
        "of the 1 added by the reproduction: 1 refined." in line
    )
    assert summary["by_source"]["project"] == {
        "confirmed": 0,
        "refined": 1,
        "corrected": 0,
        "undecidable": 0,
        "failed": 0,
    }
    assert summary["verdicts"] == list(claims.VERDICTS)


def test_perturbed_rolling_spectrum_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    from turntable import rolling

    exact = rolling.spectrum

    def perturbed(delta: Any, k: Any) -> rolling.RollingSpectrum:
        s = exact(delta, k)
        return s._replace(sigma_g=s.sigma_g * (1 + 1e-9))

    monkeypatch.setattr(rolling, "spectrum", perturbed)
    assert claims.evaluate("comparison.rolling_resistance", SMALL)["verdict"] == "failed"


def test_wrong_rolling_growth_per_turn_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    from turntable import rolling

    def wrong(delta: Any, k: Any) -> Any:
        s = rolling.spectrum(delta, k)
        return 2 * np.pi * s.sigma_g / (s.nu_g * (k + 2.0) / (k + 1.0))  # turning rate k/(k+2)

    monkeypatch.setattr(rolling, "log_growth_per_turn", wrong)
    assert claims.evaluate("comparison.rolling_resistance", SMALL)["verdict"] == "failed"


def test_rolling_solution_with_a_wrong_inertia_ratio_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    """solve with k off by 1 %: it no longer matches the constrained 3-D equations."""
    from turntable import rolling

    exact = rolling.solve

    def wrong(z0: Any, t: Any, delta: float, k: float) -> Any:
        return exact(z0, t, delta, 1.01 * k)

    monkeypatch.setattr(rolling, "solve", wrong)
    assert claims.evaluate("comparison.rolling_resistance", SMALL)["verdict"] == "failed"


def test_equal_power_on_the_slipping_spin_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    """Comparison (b) charged on the slipping ball's own spin (which a ball rolling along the
    path cannot have): the matched delta no longer agrees with the eigenvector reference."""
    from turntable import rolling

    monkeypatch.setattr(rolling, "equal_power_delta", rolling.own_spin_power_delta)
    assert claims.evaluate("comparison.rolling_resistance", SMALL)["verdict"] == "failed"


def test_slipping_orbital_rate_shifted_at_first_order_fails(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """beta - k/(k+1) of first order in 1/mu0 (instead of second): the order check fails."""
    exact = turntable.spectrum

    def shifted(mu0: Any, k: Any) -> Any:
        s = exact(mu0, k)
        return s._replace(beta=s.beta - s.alpha1)

    monkeypatch.setattr(turntable, "spectrum", shifted)
    result = claims.evaluate("comparison.rolling_resistance", SMALL)
    assert result["verdict"] == "failed"
    assert abs(result["reproduced"]["slipping_orbital_shift_order_in_mu0"] + 1.0) < 0.01


def test_rolling_orbital_rate_shifted_at_first_order_fails(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Im lambda_g - k/(k+1) of first order in delta: the order check fails (as does the
    spectrum against 50 digits)."""
    from turntable import rolling

    exact = rolling.spectrum

    def shifted(delta: Any, k: Any) -> rolling.RollingSpectrum:
        s = exact(delta, k)
        return s._replace(nu_g=s.nu_g + s.sigma_g)

    monkeypatch.setattr(rolling, "spectrum", shifted)
    result = claims.evaluate("comparison.rolling_resistance", SMALL)
    assert result["verdict"] == "failed"
    assert abs(result["reproduced"]["rolling_orbital_shift_order_in_delta"] - 1.0) < 0.01


def test_identities_carry_no_bound(evaluated_all: Callable) -> None:
    """A value that is exact by construction (key ``identity_*``) is reported, never used as
    a bound a verdict rests on."""
    for claim_id, result in evaluated_all().items():
        assert not [key for key in result["tolerance"] if key.startswith("identity_")], claim_id


def test_fig6_draws_the_fit_the_claim_reports(evaluated: Callable) -> None:
    """The claim reports the fit that Fig. 6(b) draws: limit_error_fit with the claims
    parameters."""
    from turntable.claims._core import clean

    c = claims.resolve_params(config_params())
    fit = turntable.limit_error_fit(c["state_fig4"], c["t_limit"], c["mu0_limit"], c["k_paper"])
    reproduced = evaluated("limit.convergence")["reproduced"]
    assert reproduced["position_order_k_paper"] == clean(fit.order)
    assert reproduced["position_errors_k_paper"] == clean(fit.error)


def test_limit_layer_and_drift_as_the_closed_forms_say(evaluated: Callable) -> None:
    """Across the layer the slipping ball's velocities change by dv = -k u0/(k+1) and
    dw = i u0/(k+1) (complex form), so |dv| = k |u0|/(k+1), |dw| = |u0|/(k+1) and the four
    velocities together by |u0| sqrt(1 + k^2)/(k+1), least at k = 1; at t = 1/alpha1 the
    spiral's radius has grown by e while the rolling ball's has not, so the centres are about
    (e - 1) times the initial distance from the spiral centre apart."""
    reproduced = evaluated("limit.convergence")["reproduced"]
    c = claims.resolve_params(config_params())
    k, u0 = c["k_paper"], reproduced["initial_slip"]
    assert reproduced["speed_change_across_layer_k_paper"][-1] == pytest.approx(
        k * u0 / (k + 1), rel=1e-3
    )
    assert reproduced["spin_change_across_layer_k_paper"][-1] == pytest.approx(
        u0 / (k + 1), rel=1e-3
    )
    least = min(u0 * np.sqrt(1 + q**2) / (q + 1) for q in c["k_values"])
    assert reproduced["min_velocity_change_across_layer"] == pytest.approx(least, rel=1e-2)
    assert reproduced["min_position_error_at_t_over_alpha1"] == pytest.approx(
        (np.e - 1) * reproduced["initial_distance_from_spiral_centre"], rel=1e-2
    )


def test_rolling_comparison_at_the_example_ball(evaluated: Callable) -> None:
    """Under equal power slipping is faster than rolling but not twice as fast at the
    example ball's mu0 (all above the crossover), and the ratio tends to 1 from above like
    1 + c/mu0^2: c > 0, and the ratio at mu0 = 100 is 1 + c/100^2 to first order."""
    from turntable.claims._ratios import growth_ratios

    reproduced = evaluated("comparison.rolling_resistance")["reproduced"]
    factor = reproduced["much_faster_factor"]
    crossover = reproduced["crossover_factor_equal_power_per_turn"]
    assert all(m > crossover for m in reproduced["mu0_example_ball"])
    low, high = reproduced["ratio_range_at_example_ball_equal_power_per_turn"]
    assert 1.0 < low < high < factor
    excess = reproduced["ratio_minus_1_times_mu0_squared_equal_power_per_turn"]
    assert excess > 0
    at_100 = float(growth_ratios(100.0, reproduced["k"])["equal_power"])
    assert (at_100 - 1.0) * 100.0**2 == pytest.approx(excess, rel=1e-2)


def _ratios(*values: Any) -> dict[str, np.ndarray]:
    return {f"c{i}": np.asarray(v, dtype=float) for i, v in enumerate(values)}


@pytest.mark.parametrize(
    ("ratios", "expected"),
    [
        # slipping much faster under every comparison, measure and coefficient
        pytest.param(_ratios([2.0, 50.0], [3.0, 2.0]), "confirmed", id="all-much-faster"),
        # slipping faster everywhere, but only by less than the factor somewhere
        pytest.param(_ratios([1.5, 50.0], [3.0, 2.0]), "undecidable", id="faster-not-much"),
        # slipping merely faster everywhere: not "much", and no mechanism much faster
        pytest.param(_ratios([1.1, 1.9], [1.01, 1.5]), "failed", id="merely-faster"),
        # rolling faster everywhere but never much: neither reading holds
        pytest.param(_ratios([0.6, 0.9], [0.51, 0.99]), "failed", id="rolling-merely-faster"),
        # rolling much faster everywhere: the other reading of "in this case"
        pytest.param(_ratios([0.1, 0.5], [0.2, 0.3]), "undecidable", id="rolling-much-faster"),
        # each mechanism much faster for some coefficient
        pytest.param(_ratios([10.0, 0.1], [3.0, 0.3]), "undecidable", id="depends"),
        # much faster under one comparison, alike under another
        pytest.param(_ratios([10.0, 5.0], [1.0, 1.0]), "undecidable", id="comparison"),
    ],
)
def test_much_faster_verdict_decides_each_branch(ratios: Any, expected: str) -> None:
    from turntable.claims._ratios import much_faster_verdict

    assert much_faster_verdict(ratios, 2.0) == expected


def test_much_faster_verdict_refuses_bad_input() -> None:
    from turntable.claims._ratios import much_faster_verdict

    with pytest.raises(ValueError, match="factor"):
        much_faster_verdict(_ratios([3.0]), 1.0)
    with pytest.raises(ValueError, match="ratios"):
        much_faster_verdict(_ratios([3.0, np.nan]), 2.0)
    with pytest.raises(ValueError, match="ratios"):
        much_faster_verdict(_ratios([3.0, 0.0]), 2.0)


@pytest.mark.parametrize("factor", [1.05, 1.5, 2.0, 4.0, 9.0, 20.0, 100.0])
@pytest.mark.parametrize(
    "ratios",
    [
        _ratios([2.0, 50.0], [3.0, 8.0]),
        _ratios([1.1, 1.9], [1.01, 1.5]),
        _ratios([0.1, 0.5], [0.2, 0.3]),
        _ratios([10.0, 0.1], [3.0, 0.3]),
    ],
    ids=["faster", "merely", "rolling", "depends"],
)
def test_factors_with_the_same_verdict(ratios: Any, factor: float) -> None:
    """Every factor inside the reported range gives the verdict of ``factor``; just outside
    it, another."""
    from turntable.claims._ratios import (
        factors_with_the_same_verdict,
        much_faster_verdict,
    )

    values = np.concatenate(list(ratios.values()))
    low, high = factors_with_the_same_verdict(values.min(), values.max(), factor)
    verdict = much_faster_verdict(ratios, factor)
    assert low < factor
    assert high is None or factor <= high
    inside = [x for x in (low * 1.0001, high) if x is not None and x > 1.0]
    assert all(much_faster_verdict(ratios, x) == verdict for x in inside)
    if high is not None:
        assert much_faster_verdict(ratios, high * 1.0001) != verdict
    if low > 1.0:
        assert much_faster_verdict(ratios, low) != verdict


def test_rolling_comparison_much_faster_factor_is_a_parameter(evaluated: Callable) -> None:
    """The factor comes from the parameters: with a factor above every ratio either way the
    verdict would be failed; the reported range says where that starts."""
    result = evaluated("comparison.rolling_resistance")
    assert (
        result["reproduced"]["much_faster_factor"]
        == claims.resolve_params(config_params())["much_faster_factor"]
    )
    low, high = result["reproduced"]["much_faster_factors_with_this_verdict"]
    smallest = result["reproduced"]["smallest_slipping_over_rolling"]
    largest = result["reproduced"]["largest_slipping_over_rolling"]
    # Under equal power slipping is faster everywhere, the ratio falling to one: undecidable
    # from one to its largest ratio, failed above.
    assert pytest.approx(smallest, abs=1e-9) == 1.0
    assert smallest < result["reproduced"]["much_faster_factor"] <= largest
    assert (low, high) == pytest.approx((1.0, largest))


# Reports -------------------------------------------------------------------------------


SMALL_REPORT = ["spectrum.kernel", "trajectory.untwisting_slows"]


def _report(records: list[dict[str, Any]]) -> dict[str, Any]:
    """A claims report as rule `claims` writes it, of ``records``."""
    return {
        "schema": report.SCHEMA_VERSION,
        "package": "turntable",
        "version": turntable.__version__,
        "git_commit": "unknown",
        "params": claims.resolve_params(config_params()),
        "order": [r["id"] for r in records],
        "summary": report.summarize(records),
        "claims": {r["id"]: r for r in records},
    }


@pytest.fixture
def small_report(evaluated: Callable) -> dict[str, Any]:
    return _report([evaluated(cid) for cid in SMALL_REPORT])


@pytest.fixture
def full_report(evaluated_all: Callable) -> dict[str, Any]:
    return _report(list(evaluated_all().values()))


def test_claims_command_prints_each_verdict_and_its_deciding_value(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], full_report: dict[str, Any]
) -> None:
    """``turntable claims REPORT``: one line per claim, in the report's order, with the
    verdict, the decisive key, its value and its bound exactly as the JSON holds them."""
    from turntable import cli

    data = json.loads(report.to_json(full_report))
    path = tmp_path / "claims.json"
    path.write_text(json.dumps(data), encoding="utf-8")
    assert cli.main(["claims", str(path)]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == len(data["order"])
    pattern = re.compile(r"^(\S+) +(\S+) +(\S+) = (.+) \((<=|<|>=|>|==) (.+)\)$")
    for line, cid in zip(lines, data["order"], strict=True):
        match = pattern.match(line)
        assert match, line
        shown_id, verdict, key, value, relation, limit = match.groups()
        record = data["claims"][cid]
        assert (shown_id, verdict, key) == (cid, record["verdict"], record["decisive"])
        assert value == str(record["reproduced"][key])
        assert (relation, limit) == tuple(map(str, split_bound(record["tolerance"][key])))
    # the report's own order and numbers: a float printed is the float of the JSON
    first = data["claims"][data["order"][0]]
    assert str(first["reproduced"][first["decisive"]]) in lines[0]


def test_a_verdict_other_than_the_expected_one_may_leave_the_decisive_value_unbounded() -> None:
    record = {
        "decisive": "x",
        "reproduced": {"x": 0.5},
        "tolerance": {},
        "verdict": "failed",
        "expected": "confirmed",
    }
    assert report.decisive_value(record) == "x = 0.5 (no bound: expected confirmed)"
    record["tolerance"] = {"x": {">": 1.0}}
    assert report.decisive_value(record) == "x = 0.5 (> 1.0)"


def test_claims_command_refuses_what_is_not_a_report(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], small_report: dict[str, Any]
) -> None:
    from turntable import cli

    with pytest.raises(SystemExit) as info:
        cli.main(["claims", str(tmp_path / "missing.json")])
    assert info.value.code == cli.BAD_INPUT
    assert "cannot read" in capsys.readouterr().err
    old = json.loads(report.to_json(small_report))
    for record in old["claims"].values():
        del record["decisive"]
    path = tmp_path / "old.json"
    path.write_text(json.dumps(old), encoding="utf-8")
    with pytest.raises(SystemExit) as info:
        cli.main(["claims", str(path)])
    assert info.value.code == cli.BAD_INPUT
    err = capsys.readouterr().err
    assert "not a claims report with a decisive value per claim" in err
    assert err.count("\n") == 1


def test_reports_are_deterministic(small_report: dict[str, Any]) -> None:
    """A second evaluation of the claims gives the same report, byte for byte."""
    first = report.to_json(small_report)
    second = report.to_json(_report([_evaluate(cid) for cid in SMALL_REPORT]))
    assert first == second
    assert first.endswith("\n")
    data = json.loads(first)
    assert list(data) == sorted(data)
    assert report.to_markdown(data) == report.to_markdown(json.loads(second))


def test_markdown_has_one_row_per_claim(small_report: dict[str, Any]) -> None:
    data = small_report
    text = report.to_markdown(data)
    rows = [line for line in text.splitlines() if line.startswith("| `")]
    assert len(rows) == len(data["order"])
    for row, claim_id in zip(rows, data["order"], strict=True):
        assert row.startswith(f"| `{claim_id}` |")
        assert row.count(" | ") == 5
        assert row.endswith(f"**{data['claims'][claim_id]['verdict']}** |")
    for record in data["claims"].values():
        for key in record["tolerance"]:
            assert f"`{key}` = " in text


def test_non_finite_values_are_refused() -> None:
    from turntable.claims._core import clean

    with pytest.raises(ValueError, match="non-finite"):
        clean({"x": float("nan")})
    assert clean({"a": np.float64(1.0) / 3.0, "b": np.arange(2), "c": -0.0}) == {
        "a": 0.333333333333,
        "b": [0, 1],
        "c": 0.0,
    }


def test_git_commit_outside_a_checkout_is_unknown(tmp_path: Path) -> None:
    from turntable.provenance import git_state

    assert git_state(tmp_path)[0] == "unknown"
    commit = git_state(ROOT)[0]
    assert commit == "unknown" or len(commit) == 40


def test_an_addition_never_makes_a_claim_refined() -> None:
    """The one verdict rule: a statement that holds as stated is confirmed, whatever else."""
    assert claims.decide(True, "refined") == "confirmed"
    assert claims.decide(False, "refined") == "refined"
    assert claims.decide(False) == "failed"
    with pytest.raises(ValueError, match="otherwise"):
        claims.decide(False, "confirmed")
