"""Claims of Section 1: the full 3-D equations reduce to dz/dt = L z.

`turntable.newton_euler` integrates r, v, w as 3-vectors with the spin wz
and gravity g free and the friction built from cross products; it does not
use L.  LSODA at rtol 1e-12 is accurate to about 1e-10 here (the default
DOP853 is limited by stiffness at mu0 = 10 to about 1e-7).
"""

from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose

import turntable as tt
from turntable.reference import conserved_by_definition

INTEGRATOR = {"method": "LSODA", "rtol": 1e-12, "atol": 1e-14}
T = np.linspace(0.0, 10.0, 41)


def _relative_to_state(z: np.ndarray) -> float:
    return float(np.abs(z).max())


def test_model_reduction(mu0: float, k: float, z_generic: np.ndarray) -> None:
    """model.reduction: 3-D Newton-Euler with contact kept is dz/dt = L z, (1.6)-(1.7).

    The planar state agrees with the exact solution of (1.7) (rtol 1e-8 of
    the state), the normal reaction is N = g, the centre stays at height 1
    with vz = 0, and wz stays at its initial value.
    """
    g, wz0 = 9.81, 0.7
    full = tt.newton_euler(z_generic, T, mu0, k, wz0=wz0, g=g, **INTEGRATOR)
    exact = tt.solve(z_generic, T, mu0, k)
    scale = _relative_to_state(exact)
    assert_allclose(full.z, exact, rtol=0, atol=1e-8 * scale)
    assert_allclose(full.normal, g, rtol=1e-14, atol=0)
    assert_allclose(full.v[:, 2], 0.0, rtol=0, atol=1e-14)
    assert_allclose(full.r[:, 2], 1.0, rtol=1e-14, atol=0)
    assert_allclose(full.w[:, 2], wz0, rtol=1e-14, atol=0)


@pytest.mark.parametrize(
    ("mu0", "k"),
    [pytest.param(1.0, 0.4, id="mu0=1-k=2/5"), pytest.param(10.0, 2.0 / 3.0, id="mu0=10-k=2/3")],
)
def test_model_rubber_ball(mu0: float, k: float, z_generic: np.ndarray) -> None:
    """model.rubber_ball: the spin wz (and gravity g) leave the planar motion unchanged.

    Remark 1: wz = 0 (rubber ball) and wz = 5 give the same z(t); so do
    g = 9.81 and g = 1 or 100, the reaction adjusting to N = g.
    """
    ref = tt.newton_euler(z_generic, T, mu0, k, wz0=0.0, g=9.81, **INTEGRATOR)
    spun = tt.newton_euler(z_generic, T, mu0, k, wz0=5.0, g=9.81, **INTEGRATOR)
    assert_allclose(spun.z, ref.z, rtol=0, atol=1e-12 * _relative_to_state(ref.z))
    assert_allclose(ref.w[:, 2], 0.0, rtol=0, atol=0)
    assert_allclose(spun.w[:, 2], 5.0, rtol=1e-14, atol=0)
    for g in (1.0, 100.0):
        other = tt.newton_euler(z_generic, T, mu0, k, wz0=0.0, g=g, **INTEGRATOR)
        assert_allclose(other.z, ref.z, rtol=0, atol=1e-12 * _relative_to_state(ref.z))
        assert_allclose(other.normal, g, rtol=1e-14, atol=0)


def test_newton_euler_satisfies_its_own_equations(z_generic: np.ndarray) -> None:
    """Supporting: the 3-D trajectory obeys dr/dt = v (finite differences, h = 1e-4)."""
    mu0, k, h = 1.0, 0.4, 1e-4
    t = np.array([2.0 - h, 2.0, 2.0 + h])
    full = tt.newton_euler(z_generic, t, mu0, k, **INTEGRATOR)
    drdt = (full.r[2] - full.r[0]) / (2 * h)
    assert_allclose(drdt, full.v[1], rtol=0, atol=1e-7)


def test_conserved_along_newton_euler(mu0: float, k: float, z_generic: np.ndarray) -> None:
    """Conserved quantities: k wx - vy, k wy + vx are constant along the 3-D equations."""
    full = tt.newton_euler(z_generic, T, mu0, k, wz0=0.3, **INTEGRATOR)
    c = conserved_by_definition(full.z, k)
    assert_allclose(
        c, np.tile(conserved_by_definition(z_generic, k), (T.size, 1)), rtol=0, atol=1e-9
    )
