"""A filmed trajectory: the set-up, the camera, and the CSV file of tracked positions.

A film is the position (x, y) of the ball's centre in the lab (non-rotating) frame at the
times t of the frames, in metres and seconds.  The file is UTF-8 text with delimited
fields, as spreadsheets and tracking programs write it:

- lines whose first non-blank character is ``#`` are comments, blank lines are skipped;
- the first other line is the header; it names at least the columns ``t``, ``x`` and
  ``y`` (in any order; other columns are ignored); its delimiter is the file's: a comma,
  or else a tab, or else a semicolon (`DELIMITERS`); a field may be quoted (``"t"``);
- every further line is one frame, with as many fields as the header; t, x and y are
  finite numbers and t increases strictly from frame to frame;
- a comment line containing the word ``SYNTHETIC`` (upper case) marks the film as
  simulated, not measured (``Film.synthetic``).

`read_film` refuses anything else with a `FilmError` naming the file, the line and the
column.  `write_film` writes a film; synthetic films (a header marks them SYNTHETIC and gives
their truth) come from `turntable.fit.simulate_film` and `turntable.fit.synthetic_header`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from turntable import _validate
from turntable._film_csv import (
    COLUMNS,
    DELIMITERS,
    SYNTHETIC_MARK,
    Film,
    FilmError,
    read_film,
    write_film,
)

__all__ = [
    "COLUMNS",
    "DELIMITERS",
    "EXAMPLE_FILM",
    "SYNTHETIC_MARK",
    "Camera",
    "Film",
    "FilmError",
    "Rig",
    "Setup",
    "check_setup",
    "frame_times",
    "read_film",
    "rig_from_config",
    "rpm_to_omega",
    "state_from_si",
    "state_to_si",
    "write_film",
]

#: A SYNTHETIC film that ships with the package, for trying ``turntable fit`` (its header).
EXAMPLE_FILM = Path(__file__).parent / "data" / "SYNTHETIC_slipping.csv"


class Setup(NamedTuple):
    r"""The ball and the turntable.

    Attributes
    ----------
    radius : float
        Radius R of the ball, m.
    omega : float
        Angular velocity :math:`\Omega` of the turntable, rad/s, counterclockwise in the (x, y)
        coordinates of the film (from the x axis towards the y axis).
    k : float
        Inertia ratio :math:`I / (m R^2)` of the ball (2/5 for a homogeneous ball).
    axis : tuple of float
        Position (x, y) of the turntable's axis in the film's coordinates, m.

    Examples
    --------
    >>> from turntable.film import Setup, rpm_to_omega
    >>> setup = Setup(radius=0.005, omega=rpm_to_omega(33.3))
    >>> setup.k, setup.axis
    (0.4, (0.0, 0.0))
    """

    radius: float
    omega: float
    k: float = 0.4
    axis: tuple[float, float] = (0.0, 0.0)


class Camera(NamedTuple):
    r"""How the ball is filmed.

    Attributes
    ----------
    fps : float
        Frame rate, 1/s.
    noise : float
        Standard deviation of the tracking error of each coordinate of each frame, m.
    duration : float
        Length of the film, s; the frames are at :math:`t = i / \mathrm{fps}`,
        :math:`0 \le t \le \mathrm{duration}`.

    Examples
    --------
    >>> from turntable.film import Camera, frame_times
    >>> camera = Camera(fps=30.0, noise=2e-4, duration=10.0)
    >>> frame_times(camera).size
    301
    """

    fps: float
    noise: float
    duration: float


def rpm_to_omega(rpm: float) -> float:
    r"""Return :math:`\Omega = 2\pi\,\mathrm{rpm}/60`, rad/s, of ``rpm`` revolutions per minute.

    Parameters
    ----------
    rpm : float
        Revolutions per minute, finite and > 0.

    Returns
    -------
    float
        Ω, rad/s.

    Examples
    --------
    >>> from turntable.film import rpm_to_omega
    >>> print(f"{rpm_to_omega(33.3):.4f} rad/s")
    3.4872 rad/s
    """
    return 2.0 * math.pi * _validate.positive_scalar("rpm", rpm) / 60.0


def check_setup(setup: Setup) -> Setup:
    """Return ``setup`` with its numbers validated (ValueError naming a bad one).

    Parameters
    ----------
    setup : Setup
        Ball and turntable.

    Returns
    -------
    Setup
        The same values, as floats.

    Raises
    ------
    ValueError
        If a number is not finite, or the radius, Ω or k is not > 0.

    Examples
    --------
    >>> from turntable.film import Setup, check_setup
    >>> check_setup(Setup(radius=0.005, omega=3.5))
    Setup(radius=0.005, omega=3.5, k=0.4, axis=(0.0, 0.0))
    >>> check_setup(Setup(radius=-0.005, omega=3.5))
    Traceback (most recent call last):
    ...
    ValueError: radius must be ...
    """
    radius = _validate.positive_scalar("radius", setup.radius)
    omega = _validate.positive_scalar("omega", setup.omega)
    k = _validate.positive_scalar("k", setup.k)
    axis = tuple(_validate.finite_scalar("axis", a) for a in setup.axis)
    if len(axis) != 2:
        raise ValueError(f"axis must be two finite numbers (x, y); got {setup.axis!r}")
    return Setup(radius, omega, k, (axis[0], axis[1]))


def frame_times(camera: Camera) -> NDArray[np.float64]:
    r"""Return the times :math:`i/f`, s, of the frames in [0, ``duration``] at ``fps`` :math:`f`.

    Parameters
    ----------
    camera : Camera
        Frame rate and duration.

    Returns
    -------
    numpy.ndarray
        The times, s, from 0.

    Examples
    --------
    >>> from turntable.film import Camera, frame_times
    >>> frame_times(Camera(fps=4.0, noise=2e-4, duration=1.0))
    array([0.  , 0.25, 0.5 , 0.75, 1.  ])
    """
    fps = _validate.positive_scalar("fps", camera.fps)
    duration = _validate.positive_scalar("duration", camera.duration)
    return np.arange(math.floor(duration * fps * (1.0 + 1e-12)) + 1) / fps


def state_from_si(
    position: ArrayLike,
    velocity: ArrayLike,
    spin: ArrayLike,
    setup: Setup,
) -> NDArray[np.float64]:
    r"""Return the dimensionless state (x, y, vx, vy, wx, wy) of a ball given in SI units.

    Parameters
    ----------
    position : array_like
        Position (x, y) of the centre in the film's coordinates, m.
    velocity : array_like
        Velocity of the centre in the lab frame, m/s.
    spin : array_like
        Horizontal components of the ball's angular velocity in the lab frame, rad/s.
    setup : Setup
        Ball and turntable.

    Returns
    -------
    numpy.ndarray
        :math:`(r - \mathrm{axis}) / R`, :math:`v / (R \Omega)`, :math:`w / \Omega`.

    See Also
    --------
    turntable.film.state_to_si : The inverse.

    Notes
    -----
    The paper's units (Section 1): length :math:`R`, time :math:`1/\Omega`; the spin
    :math:`w` is in units of :math:`\Omega`, so that the slip velocity is
    :math:`u = v + \gamma \times w - \gamma \times r` (the no-slip constraint of a ball on
    a plane turning at rate 1).

    Examples
    --------
    In units of :math:`R` and :math:`1/\Omega`: 5 cm from the axis is 10 radii of a 1 cm ball:

    >>> from turntable.film import Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=2.0)
    >>> state_from_si([0.05, 0.0], [0.0, 0.01], [0.0, 0.0], setup)
    array([10.,  0.,  0.,  1.,  0.,  0.])
    """
    setup = check_setup(setup)
    out = np.empty(6)
    for i, (name, value) in enumerate((("position", position), ("velocity", velocity))):
        arr = _validate._as_float_array(name, value, "two finite numbers")
        if arr.shape != (2,) or not np.all(np.isfinite(arr)):
            raise ValueError(f"{name} must be two finite numbers; got {value!r}")
        out[2 * i : 2 * i + 2] = arr
    arr = _validate._as_float_array("spin", spin, "two finite numbers")
    if arr.shape != (2,) or not np.all(np.isfinite(arr)):
        raise ValueError(f"spin must be two finite numbers; got {spin!r}")
    out[0:2] = (out[0:2] - np.asarray(setup.axis)) / setup.radius
    out[2:4] /= setup.radius * setup.omega
    out[4:6] = arr / setup.omega
    return out


def state_to_si(state: ArrayLike, setup: Setup) -> dict[str, list[float]]:
    r"""Return the dimensionless state as position (m), velocity (m/s), spin (rad/s).

    Parameters
    ----------
    state : array_like
        Dimensionless state (x, y, vx, vy, wx, wy).
    setup : Setup
        Ball and turntable (radius, :math:`\Omega`, axis).

    Returns
    -------
    dict
        ``position_m``, ``velocity_m_s`` and ``spin_rad_s``, each a list of two floats.

    See Also
    --------
    state_from_si : The inverse.

    Examples
    --------
    >>> from turntable.film import Setup, state_to_si
    >>> state_to_si([10, 0, 0, 1, 0, 0], Setup(radius=0.005, omega=2.0))
    {'position_m': [0.05, 0.0], 'velocity_m_s': [0.0, 0.01], 'spin_rad_s': [0.0, 0.0]}
    """
    setup = check_setup(setup)
    z = _validate.state("state", state)
    return {
        "position_m": [float(v) for v in z[0:2] * setup.radius + np.asarray(setup.axis)],
        "velocity_m_s": [float(v) for v in z[2:4] * setup.radius * setup.omega],
        "spin_rad_s": [float(v) for v in z[4:6] * setup.omega],
    }


class Rig(NamedTuple):
    """A filmed experiment: ball and turntable, camera, the ball's start, its mass (kg).

    Examples
    --------
    >>> from turntable.film import Camera, Rig, Setup, state_from_si
    >>> setup = Setup(radius=0.005, omega=3.49)
    >>> start = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    >>> rig = Rig(setup, Camera(fps=240.0, noise=2e-4, duration=10.0), start, mass=0.00411)
    >>> rig.state0
    array([10.,  0.,  0.,  0.,  0.,  0.])
    """

    setup: Setup
    camera: Camera
    state0: NDArray[np.float64]
    mass: float


def rig_from_config(section: Mapping[str, Any]) -> Rig:
    """Return the `Rig` of the workflow's configuration section ``film`` (SI units).

    Parameters
    ----------
    section : mapping
        Keys radius_m, mass_kg, k, rpm, axis_m, fps, noise_m, duration_s,
        start_position_m, start_velocity_m_s, start_spin_rad_s (see
        workflow/schemas/config.schema.yaml).

    Returns
    -------
    Rig
        ``state0`` is the dimensionless start (`state_from_si`) of the slipping ball.

    Examples
    --------
    >>> from turntable.film import rig_from_config
    >>> rig = rig_from_config({
    ...     "radius_m": 0.005, "mass_kg": 0.00411, "k": 0.4, "rpm": 33.3,
    ...     "axis_m": [0, 0], "fps": 240.0, "noise_m": 2e-4, "duration_s": 10.0,
    ...     "start_position_m": [0.05, 0], "start_velocity_m_s": [0, 0],
    ...     "start_spin_rad_s": [0, 0]})
    >>> rig.camera, rig.state0
    (Camera(fps=240.0, noise=0.0002, duration=10.0), array([10.,  0.,  0.,  0.,  0.,  0.]))
    """
    axis = section["axis_m"]
    setup = check_setup(
        Setup(section["radius_m"], rpm_to_omega(section["rpm"]), section["k"], (axis[0], axis[1]))
    )
    camera = Camera(section["fps"], section["noise_m"], section["duration_s"])
    state0 = state_from_si(
        section["start_position_m"],
        section["start_velocity_m_s"],
        section["start_spin_rad_s"],
        setup,
    )
    return Rig(setup, camera, state0, _validate.positive_scalar("mass", section["mass_kg"]))
