"""The film shipped with the package (`turntable.film.EXAMPLE_FILM`) is what the package's
own simulation writes from the values its header states, and `turntable fit` finds them."""

from __future__ import annotations

import json
import subprocess
import sys

from turntable import film, fit
from turntable.film import EXAMPLE_FILM, Camera, Setup, rpm_to_omega, state_from_si


def test_example_film_is_the_simulation_it_says_it_is(tmp_path) -> None:
    setup = Setup(radius=0.005, omega=rpm_to_omega(100.0 / 3.0), k=0.4)
    camera = Camera(fps=30.0, noise=2e-4, duration=10.0)
    z0 = state_from_si([0.05, 0.0], [0.0, 0.0], [0.0, 0.0], setup)
    args = ("slipping", 3.0, z0, setup, camera, 1)
    written = tmp_path / "film.csv"
    film.write_film(written, fit.simulate_film(*args), fit.synthetic_header(*args))
    assert written.read_bytes() == EXAMPLE_FILM.read_bytes()
    assert film.read_film(EXAMPLE_FILM).synthetic


def test_fit_of_the_example_film_finds_its_truth() -> None:
    command = [sys.executable, "-m", "turntable", "fit", str(EXAMPLE_FILM), "--radius", "0.005"]
    out = subprocess.run(
        [*command, "--rpm", "33.333333333333336"], capture_output=True, text=True, check=True
    )
    result = json.loads(out.stdout)
    assert result["selected"] == "slipping"
    assert result["selection"]["decisive"]
    slipping = result["slipping"]
    assert abs(slipping["mu0"] - 3.0) < 4 * slipping["mu0_stderr"]
