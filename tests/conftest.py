"""Hypothesis settings and fixtures shared by the tests.

Independent reference computations (sympy, mpmath, numpy) live in
``src/turntable/reference/`` (shared with the claims checks and the benchmarks).
"""

from __future__ import annotations

import os

# One BLAS thread per process, set before numpy loads OpenBLAS (and inherited by the
# commands the tests start): the matrices here are small, and with pytest -n 2 on two cores
# the threads of OpenBLAS only wait for each other (a 6x6 expm takes ms instead of 50 us).
for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import functools  # noqa: E402
import threading  # noqa: E402
from collections.abc import Callable, Iterator, Sequence  # noqa: E402
from pathlib import Path  # noqa: E402
from typing import Any  # noqa: E402

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import settings  # noqa: E402
from numpy.typing import NDArray  # noqa: E402

import ci_build  # noqa: E402
from shared_build import computed_once, shared_dir  # noqa: E402

# Parametrized grids shared by several modules ------------------------------------------

K_PARAMS = [
    pytest.param(2.0 / 5.0, id="k=2/5"),
    pytest.param(2.0 / 3.0, id="k=2/3"),
    pytest.param(1.0, id="k=1"),
]
MU0_PARAMS = [
    pytest.param(0.1, id="mu0=0.1"),
    pytest.param(1.0, id="mu0=1"),
    pytest.param(10.0, id="mu0=10"),
]

settings.register_profile("turntable", deadline=None, max_examples=60, derandomize=True)
settings.load_profile("turntable")


@pytest.fixture(scope="module", params=K_PARAMS)
def k(request: pytest.FixtureRequest) -> float:
    """Inertia ratios: homogeneous ball, thin shell, and k = 1."""
    return request.param


@pytest.fixture(scope="module", params=MU0_PARAMS)
def mu0(request: pytest.FixtureRequest) -> float:
    """Friction coefficients below, at and above the turntable's rate."""
    return request.param


@pytest.fixture(scope="module")
def z_generic() -> NDArray[np.float64]:
    """A state with every component nonzero and slipping (u != 0)."""
    return np.array([1.0, 1.0, 0.3, -0.2, 0.1, 0.5])


@pytest.fixture(scope="module")
def z_fig4() -> NDArray[np.float64]:
    """The initial state of Fig. 4: x = y = 1, v = 0, wx = 0, wy = 1."""
    return np.array([1.0, 1.0, 0.0, 0.0, 0.0, 1.0])


@pytest.fixture(scope="session")
def computed(
    tmp_path_factory: pytest.TempPathFactory, worker_id: str
) -> Callable[[str, Sequence[str], Callable[[str], Any]], dict[str, Any]]:
    """``computed(name, keys, compute)``: ``{key: compute(key)}``, each value computed once
    per test run and shared by the xdist workers (`shared_build.computed_once`)."""
    return functools.partial(computed_once, shared_dir(tmp_path_factory, worker_id))


# The shared build ------------------------------------------------------------------------
# A minute of CPU (32 jobs): a test that reads it is marked slow (run by make test-slow and
# CI). It starts with the session, in the background of one worker, and the tests that read
# it run last, so that no worker waits for it idle.

BUILD_FIXTURES = {"clean_build", "build_record"}


def _reads_build(item: pytest.Item) -> bool:
    return bool(BUILD_FIXTURES & set(getattr(item, "fixturenames", ())))


@pytest.hookimpl(tryfirst=True)  # before -m selects by the marks
def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        if _reads_build(item):
            item.add_marker(pytest.mark.slow)
    items.sort(key=_reads_build)


@pytest.fixture(scope="session", autouse=True)
def _build_in_background(
    request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory, worker_id: str
) -> Iterator[None]:
    if not any(map(_reads_build, request.session.items)) or worker_id not in ("master", "gw0"):
        yield
        return
    # The first call of getbasetemp() makes (and first empties) the worker's directory: here,
    # before the thread, which would otherwise empty it under a test's tmp_path.
    tmp_path_factory.getbasetemp()
    thread = threading.Thread(target=ci_build.shared_build, args=(tmp_path_factory, worker_id))
    thread.start()
    yield
    thread.join()


@pytest.fixture(scope="session")
def build_record(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> tuple[Path, dict]:
    """The directory of the shared build (`ci_build`) and the record of its plan and build."""
    return ci_build.shared_build(tmp_path_factory, worker_id)


@pytest.fixture(scope="session")
def clean_build(build_record: tuple[Path, dict]) -> Path:
    """The directory of the shared build, which succeeded."""
    workdir, record = build_record
    assert record["build_returncode"] == 0, record["build_log"]
    return workdir


@pytest.fixture(scope="session")
def shared_tmp(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> Path:
    """A directory shared by the xdist workers of this run."""
    return shared_dir(tmp_path_factory, worker_id)
