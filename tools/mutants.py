"""Mutation check: every deliberate error in the physics must fail a test.

Usage::

    .venv/bin/python tools/mutants.py [--fast] [--only NAME ...]

For each mutant below, ``src/`` and the model-core tests are copied into a
temporary directory, the mutation is applied to the copy as a text
substitution (it is an error if the text does not occur exactly as often as
expected), and pytest runs the tests against the copy
(``PYTHONPATH=<tmp>/src``, ``-p no:cacheprovider -n 2``).  The unmutated
copy is run first and must pass.  The script prints, for each mutant, the
tests that failed, and exits with status 1 if any mutant survives (no test
failed) or if the baseline fails.

``--fast`` adds ``-x`` (stop at the first failure): quicker, but it reports
only one failing test per mutant.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: The tests of the model core (other test files check the pipeline, CI, etc.).
OWN_TESTS = (
    "test_spectrum.py",
    "test_solution.py",
    "test_model.py",
    "test_limit.py",
    "test_validation.py",
    "test_rolling.py",
)


@dataclass(frozen=True)
class Mutant:
    """A named set of text substitutions in files under src/turntable/."""

    name: str
    description: str
    edits: tuple[tuple[str, str, str, int], ...]  # (file, old, new, expected count)


MUTANTS = [
    Mutant(
        "matrix-sign",
        "flip the sign of the -mu0 J (spin) block in the v row of L (system_matrix)",
        (
            (
                "spectrum.py",
                "[mu0 * _J, -mu0 * _I2, -mu0 * _J]",
                "[mu0 * _J, -mu0 * _I2, mu0 * _J]",
                1,
            ),
        ),
    ),
    Mutant(
        "ratio-k-over-k+2",
        "replace k/(k+1) by k/(k+2) everywhere in spectrum.py",
        (("spectrum.py", "kk = k / (k + 1.0)", "kk = k / (k + 2.0)", 3),),
    ),
    Mutant(
        "centre-sign",
        "y0 = wy - vx/k instead of wy + vx/k, wherever the centre is computed",
        (
            ("solution.py", "(k * z0[5] + z0[2]) / k", "(k * z0[5] - z0[2]) / k", 1),
            (
                "solution.py",
                "rc = w0 + 1j * v0 / k",
                "rc = w0 + 1j * complex(-v0.real, v0.imag) / k",
                2,
            ),
        ),
    ),
    Mutant(
        "friction-sign",
        "friction pushes along the slip instead of against it (newton_euler)",
        (("newton_euler.py", "friction = -mu0 * u", "friction = mu0 * u", 1),),
    ),
    Mutant(
        "eps-power",
        "eps = 4 kk / mu0 instead of 4 kk^2 / mu0 in the spectrum",
        (("spectrum.py", "eps = 4.0 * kk * kk / mu0", "eps = 4.0 * kk / mu0", 1),),
    ),
    Mutant(
        "decaying-amplitude",
        "wrong sign of v0 in the amplitude of the decaying modes (modal_terms)",
        (
            (
                "solution.py",
                "amp_m = (c.lp * c.rho0 - c.v0) / d",
                "amp_m = (c.lp * c.rho0 + c.v0) / d",
                1,
            ),
        ),
    ),
    Mutant(
        "no-slip-rate",
        "the no-slip orbit turns at k/(k+2) instead of k/(k+1) (nonholonomic)",
        (("solution.py", "omega = k / (k + 1.0)", "omega = k / (k + 2.0)", 1),),
    ),
    Mutant(
        "spin-from-velocity",
        "wy = wy_c + vx / k instead of wy_c - vx / k in solve (w = r_c - i v / k)",
        (("solution.py", "m[1:, 5] = -v[:, 0] / k", "m[1:, 5] = v[:, 0] / k", 1),),
    ),
    Mutant(
        "rolling-growth-ratio",
        "sigma_g = 4 delta q / (A (k + 1 + q)) instead of (k + 2 + q) (rolling spectrum)",
        (
            (
                "rolling.py",
                "sigma_g = 4.0 * d * qh / (a * (k + 2.0 + q))",
                "sigma_g = 4.0 * d * qh / (a * (k + 1.0 + q))",
                1,
            ),
        ),
    ),
    Mutant(
        "rolling-turning-rate",
        "nu_g = (k + q) / (2 (k + 2)) instead of / (2 (k + 1)) (rolling spectrum)",
        (
            (
                "rolling.py",
                "nu_g = (k + q) / (2.0 * (k + 1.0))",
                "nu_g = (k + q) / (2.0 * (k + 2.0))",
                1,
            ),
        ),
    ),
    Mutant(
        "rolling-centre-frequency-sign",
        "the centre's root turns the other way: nu_c = +4 delta^2 / (A (q + k))",
        (
            (
                "rolling.py",
                "nu_c = -4.0 * d * d / (a * (q + k))",
                "nu_c = 4.0 * d * d / (a * (q + k))",
                1,
            ),
        ),
    ),
    Mutant(
        "rolling-amplitude-sign",
        "A_g = (v0 + lambda_c r0) / (lambda_g - lambda_c) instead of v0 - lambda_c r0 (rolling)",
        (("rolling.py", "(v0 - lc * r0) / d", "(v0 + lc * r0) / d", 1),),
    ),
    Mutant(
        "rolling-constraint-sign",
        "w = r - i v instead of w = r + i v in the rolling solution",
        (("rolling.py", "w = amp + 1j * v", "w = amp - 1j * v", 1),),
    ),
    Mutant(
        "rolling-torque-sign",
        "the rolling-resistance moment drives the spin (+delta w_h) in the 3-D equations",
        (
            (
                "rolling.py",
                "return -delta * np.array([w[0], w[1], 0.0])",
                "return delta * np.array([w[0], w[1], 0.0])",
                1,
            ),
        ),
    ),
    Mutant(
        "equal-power-ratio",
        "(k u) instead of ((k + 1) u): x = k alpha1 in equal_power_delta",
        (("rolling.py", "x = (k + 1.0) * sp.alpha1", "x = k * sp.alpha1", 1),),
    ),
    Mutant(
        "comparison-swap",
        "matched_delta returns the equal-decay delta for the equal-power comparison",
        (
            (
                "rolling.py",
                'if comparison == "equal_power":\n        return equal_power_delta(mu0, k)',
                'if comparison == "equal_power":\n        return equal_decay_delta(mu0, k)',
                1,
            ),
        ),
    ),
]


def _own_tests() -> list[Path]:
    return [ROOT / "tests" / name for name in OWN_TESTS]


def _prepare(tmp: Path) -> list[str]:
    """Copy src/, the model-core tests and pyproject.toml into tmp; return the test paths."""
    shutil.copytree(
        ROOT / "src", tmp / "src", ignore=shutil.ignore_patterns("__pycache__", "*.egg-info")
    )
    (tmp / "tests").mkdir()
    for name in ("conftest.py", "reference.py"):
        shutil.copy2(ROOT / "tests" / name, tmp / "tests" / name)
    tests = []
    for path in _own_tests():
        shutil.copy2(path, tmp / "tests" / path.name)
        tests.append(f"tests/{path.name}")
    shutil.copy2(ROOT / "pyproject.toml", tmp / "pyproject.toml")
    return tests


def _apply(tmp: Path, mutant: Mutant) -> None:
    for file, old, new, count in mutant.edits:
        path = tmp / "src" / "turntable" / file
        text = path.read_text()
        found = text.count(old)
        if found != count:
            raise SystemExit(
                f"mutant {mutant.name}: expected {count} occurrence(s) of {old!r} "
                f"in src/turntable/{file}, found {found}"
            )
        path.write_text(text.replace(old, new))


def _run(tmp: Path, tests: list[str], fast: bool) -> tuple[int, list[str], float]:
    """Run pytest in tmp against tmp/src; return (exit code, failed test ids, seconds)."""
    env = dict(os.environ, PYTHONPATH=str(tmp / "src"), PYTHONDONTWRITEBYTECODE="1")
    check = subprocess.run(
        [sys.executable, "-c", "import turntable; print(turntable.__file__)"],
        env=env,
        cwd=tmp,
        capture_output=True,
        text=True,
        check=True,
    )
    if not Path(check.stdout.strip()).is_relative_to(tmp):
        raise SystemExit(f"the copy is not the package imported: {check.stdout.strip()}")
    report = tmp / "report.xml"
    cmd = [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q", "-n", "2"]
    cmd += ["--junitxml", str(report), *(["-x"] if fast else []), *tests]
    start = time.perf_counter()
    proc = subprocess.run(cmd, env=env, cwd=tmp, capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - start
    failed = []
    if report.exists():
        for case in ET.parse(report).getroot().iter("testcase"):
            if case.find("failure") is not None or case.find("error") is not None:
                failed.append(f"{case.get('classname')}::{case.get('name')}")
        report.unlink()
    if proc.returncode not in (0, 1) or (proc.returncode == 1 and not failed):
        print(proc.stdout[-3000:], proc.stderr[-3000:], sep="\n", file=sys.stderr)
        raise SystemExit(f"pytest could not run (exit code {proc.returncode})")
    return proc.returncode, failed, seconds


def _summarise(failed: list[str]) -> str:
    """One line per failing test function, with how many of its cases failed."""
    counts: dict[str, int] = {}
    for node in failed:
        function = node.split("[")[0]
        counts[function] = counts.get(function, 0) + 1
    return "\n".join(f"      {name} ({n})" for name, n in sorted(counts.items()))


def main(argv: list[str] | None = None) -> int:
    """Run the baseline and every mutant; return 1 if any mutant survives."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fast", action="store_true", help="stop each run at the first failure")
    parser.add_argument("--only", nargs="+", metavar="NAME", help="run only these mutants")
    args = parser.parse_args(argv)
    mutants = [m for m in MUTANTS if not args.only or m.name in args.only]
    if args.only and len(mutants) != len(args.only):
        known = ", ".join(m.name for m in MUTANTS)
        raise SystemExit(f"unknown mutant in {args.only}; known: {known}")

    with tempfile.TemporaryDirectory(prefix="turntable-mutants-") as base:
        base_dir = Path(base)
        tmp = base_dir / "baseline"
        tmp.mkdir()
        tests = _prepare(tmp)
        code, failed, seconds = _run(tmp, tests, args.fast)
        print(f"baseline (no mutation): {len(failed)} failed, {seconds:.1f} s")
        if code != 0:
            print(_summarise(failed))
            print("the unmutated code must pass its tests first")
            return 1

        survivors = []
        for mutant in mutants:
            tmp = base_dir / mutant.name
            tmp.mkdir()
            tests = _prepare(tmp)
            _apply(tmp, mutant)
            code, failed, seconds = _run(tmp, tests, args.fast)
            status = "killed" if failed else "SURVIVED"
            print(f"{mutant.name}: {status} ({len(failed)} failed, {seconds:.1f} s)")
            print(f"    {mutant.description}")
            if failed:
                print(_summarise(failed))
            else:
                survivors.append(mutant.name)
            shutil.rmtree(tmp)

    if survivors:
        print(f"surviving mutants: {', '.join(survivors)}")
        return 1
    print(f"all {len(mutants)} mutants killed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
