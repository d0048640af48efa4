"""The claims registry: one test per claim of the paper, plus its own guarantees.

Each claim is checked with the parameters of the ``claims:`` section of
config/config.yaml, the same the workflow uses for results/claims.json.  A
verdict other than the expected one (``confirmed``, or ``refined`` for the claims in
`REFINED_IDS`) fails the suite.  Further tests break the model on purpose
and require the affected check to notice.
"""

from __future__ import annotations

import functools
import json
import math
from pathlib import Path
from typing import Any

import mpmath
import numpy as np
import pytest
import yaml

import turntable
from turntable import claims
from turntable.claims import report

ROOT = Path(__file__).resolve().parents[1]

#: The claim identifiers listed in the project's notes on the paper.
PAPER_IDS = {
    "model.reduction",
    "model.rubber_ball",
    "spectrum.char_poly",
    "spectrum.kernel",
    "spectrum.roots",
    "spectrum.unstable_focus",
    "solution.decomposition",
    "solution.centre",
    "solution.damping_ratio",
    "solution.fast_transient",
    "trajectory.spiral",
    "trajectory.untwisting_slows",
    "limit.expansion",
    "limit.frequency",
    "limit.convergence",
    "comparison.rolling_resistance",
}

#: Claims whose truth depends on values the paper does not give.
UNDECIDABLE_IDS = {"comparison.rolling_resistance"}

#: Claims whose statement holds only in a narrower form; every other claim is confirmed.
REFINED_IDS = {
    "solution.centre",
    "solution.damping_ratio",
    "solution.fast_transient",
    "trajectory.untwisting_slows",
    "limit.convergence",
}

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
}


@functools.cache
def config_params() -> dict[str, Any]:
    """The ``claims:`` section of config/config.yaml (the workflow's parameters)."""
    with open(ROOT / "config" / "config.yaml", encoding="utf-8") as fh:
        return yaml.safe_load(fh)["claims"]


@functools.cache
def evaluated(claim_id: str) -> dict[str, Any]:
    return claims.evaluate(claim_id, config_params())


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
def test_claim_has_its_expected_verdict(claim_id: str) -> None:
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
    expected = "refined" if claim_id in REFINED_IDS else "confirmed"
    if claim_id in UNDECIDABLE_IDS:
        expected = "undecidable"
    assert result["verdict"] == expected, f"{claim_id}: {result['evidence']}"


def test_registry_covers_every_claim_of_the_notes() -> None:
    ids = set(claims.claim_ids())
    assert ids >= PAPER_IDS
    for claim_id in ids - PAPER_IDS:
        assert claims.get(claim_id).source == "project"
    for claim_id in PAPER_IDS:
        assert claims.get(claim_id).source == "paper"


def test_every_claim_records_where_it_is() -> None:
    for claim_id in claims.claim_ids():
        c = claims.get(claim_id)
        assert c.where.section, claim_id
        assert c.claim.endswith("."), claim_id
        if c.paper_value is not None:
            assert c.paper_value.get("text"), claim_id


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
        ("no_such_key", 1),
    ],
)
def test_bad_params_raise_naming_the_key(key: str, value: Any) -> None:
    with pytest.raises(ValueError, match=key):
        claims.resolve_params({key: value})


def test_config_section_matches_the_defaults_and_the_schema() -> None:
    with open(ROOT / "workflow" / "schemas" / "config.schema.yaml", encoding="utf-8") as fh:
        schema = yaml.safe_load(fh)["properties"]["claims"]
    assert set(schema["properties"]) == set(claims.DEFAULT_PARAMS)
    assert set(schema["required"]) == set(claims.DEFAULT_PARAMS)
    assert schema["default"] == claims.DEFAULT_PARAMS
    for key, prop in schema["properties"].items():
        assert prop["default"] == claims.DEFAULT_PARAMS[key], key
        assert prop.get("description"), key
    assert claims.resolve_params(config_params()) == claims.resolve_params(claims.DEFAULT_PARAMS)


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
    from turntable.claims import _reference as ref

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


# Reports -------------------------------------------------------------------------------


def _small_report() -> dict[str, Any]:
    ids = ["spectrum.kernel", "trajectory.untwisting_slows"]
    records = [claims.evaluate(i, config_params()) for i in ids]
    return {
        "schema": report.SCHEMA_VERSION,
        "package": "turntable",
        "version": turntable.__version__,
        "git_commit": "unknown",
        "params": claims.resolve_params(config_params()),
        "order": ids,
        "summary": {v: sum(r["verdict"] == v for r in records) for v in claims.VERDICTS}
        | {"total": len(records)},
        "claims": {r["id"]: r for r in records},
    }


def test_reports_are_deterministic() -> None:
    first = report.to_json(_small_report())
    second = report.to_json(_small_report())
    assert first == second
    assert first.endswith("\n")
    data = json.loads(first)
    assert list(data) == sorted(data)
    assert report.to_markdown(data) == report.to_markdown(json.loads(second))


def test_markdown_has_one_row_per_claim() -> None:
    data = _small_report()
    text = report.to_markdown(data)
    rows = [line for line in text.splitlines() if line.startswith("| `")]
    assert len(rows) == len(data["order"])
    for row, claim_id in zip(rows, data["order"], strict=True):
        assert row.startswith(f"| `{claim_id}` |")
        assert row.count(" | ") == 5
        assert row.endswith(f"**{data['claims'][claim_id]['verdict']}** |")


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
    assert report.git_commit(tmp_path) == "unknown"
    commit = report.git_commit(ROOT)
    assert commit == "unknown" or len(commit) == 40
