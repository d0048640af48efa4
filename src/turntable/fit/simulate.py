"""Synthetic films: the exact motion of one model plus Gaussian tracking noise."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from turntable import _validate
from turntable.film import Camera, Film, Setup, frame_times, state_to_si
from turntable.fit.models import COEFFICIENT, positions


def simulate_film(
    model: str,
    coefficient: float,
    state0: ArrayLike,
    setup: Setup,
    camera: Camera,
    seed: int,
) -> Film:
    r"""Return a synthetic film: the exact motion of one model plus Gaussian tracking noise.

    Parameters
    ----------
    model : {"slipping", "rolling_resistance"}
        The slipping ball of the paper (`turntable.solve`, coefficient :math:`\mu_0`) or the
        ball rolling without slipping with rolling resistance (`turntable.rolling.solve`,
        coefficient :math:`\delta`).
    coefficient : float
        :math:`\mu_0 / (m \Omega)` or :math:`\delta / (m R^2 \Omega)`, dimensionless, > 0.
    state0 : array_like
        Dimensionless state (x, y, vx, vy, wx, wy) at :math:`t = 0` (see
        `~turntable.film.state_from_si`); for the rolling model it must satisfy the no-slip
        constraint.
    setup : Setup
        Ball and turntable.
    camera : Camera
        Frame rate, noise and duration.
    seed : int
        Seed of the noise (`numpy.random.default_rng`).

    Returns
    -------
    Film
        Frames at :math:`t = i / \mathrm{fps}`;
        :math:`(x, y) = R\, (x, y)(\Omega t) + \mathrm{axis} + \mathrm{noise}`, each coordinate
        with independent :math:`N(0, \text{noise}^2)` errors; marked ``synthetic``.

    See Also
    --------
    turntable.fit.fit_film : Its fit.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> film = fit.simulate_film("slipping", 3.0, z0, setup, camera, seed=1)
    >>> len(film.t), film.synthetic
    (61, True)
    """

    t = frame_times(camera)
    noise = float(camera.noise)
    if not (math.isfinite(noise) and noise >= 0):
        raise ValueError(f"noise must be a finite number >= 0; got {camera.noise!r}")
    xy = positions(model, coefficient, state0, t, setup)
    rng = np.random.default_rng(seed)
    xy = xy + noise * rng.standard_normal(xy.shape)
    return Film(t, xy[:, 0], xy[:, 1], synthetic=True)


def synthetic_header(
    model: str,
    coefficient: float,
    state0: ArrayLike,
    setup: Setup,
    camera: Camera,
    seed: int,
) -> list[str]:
    """Return the comment lines that mark a film SYNTHETIC and give its true parameters.

    Parameters
    ----------
    model, coefficient, state0, setup, camera, seed
        The arguments of `simulate_film` that made the film.

    Returns
    -------
    list of str
        The comment lines, without the ``#``.

    Examples
    --------
    >>> from turntable import fit
    >>> from turntable.film import Camera, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.5, k=0.4)
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=2.0)
    >>> z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> fit.synthetic_header("slipping", 3.0, z0, setup, camera, seed=1)[:2]
    ['SYNTHETIC DATA: simulated by turntable.fit.simulate_film, not measured.',
     'truth: model = slipping, mu0 = 3.0 (dimensionless)']
    """

    z0 = _validate.state("state0", state0)
    si = state_to_si(z0, setup)
    return [
        "SYNTHETIC DATA: simulated by turntable.fit.simulate_film, not measured.",
        f"truth: model = {model}, {COEFFICIENT[model]} = {coefficient!r} (dimensionless)",
        f"truth: k = {setup.k!r}, radius_m = {setup.radius!r}, omega_rad_s = {setup.omega!r}, "
        f"axis_m = {list(setup.axis)!r}",
        f"truth: state0 = {[float(v) for v in z0]!r} (dimensionless, at t = 0); "
        f"position_m = {si['position_m']!r}, velocity_m_s = {si['velocity_m_s']!r}, "
        f"spin_rad_s = {si['spin_rad_s']!r}",
        f"camera: fps = {camera.fps!r}, noise_m = {camera.noise!r} (per coordinate), "
        f"duration_s = {camera.duration!r}, seed = {seed}",
    ]
