"""Mutation check: every deliberate error in the physics must fail a test.

Usage::

    .venv/bin/python tools/mutants.py [--fast] [--only NAME ...]

For each mutant below, ``src/`` and the mutant's tests (by default the
model-core tests) are copied into a temporary directory, the mutation is
applied to the copy as a text substitution (it is an error if the text does
not occur exactly as often as expected), and pytest runs the tests against
the copy (``PYTHONPATH=<tmp>/src``, ``-p no:cacheprovider -n 2 -m ""``: slow tests too, and the
mutant's ``-k`` expression if it has one).  The unmutated copy is run first,
once for each set of tests, and must pass.  The script prints, for each mutant, the
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
    "test_large_friction_limit.py",
    "test_limits.py",
    "test_validation.py",
    "test_rolling.py",
)


#: Tests of the parameter study, without the one that plans the whole workflow.
STUDY_TESTS = ("test_study.py",)
STUDY_KEYWORD = "not slurm"

#: Tests of the claims registry.
CLAIMS_TESTS = ("test_claims.py",)

#: The test of the comparison.rolling_resistance claim alone (its expected verdict).
ROLLING_CLAIM = "test_claim_has_its_expected_verdict and rolling_resistance"

#: The second routes of the numbers the article prints.
PRINTED_TESTS = ("test_printed_numbers.py",)

#: Tests of the fit of a film.
FIT_TESTS = ("test_fit.py",)


@dataclass(frozen=True)
class Mutant:
    """A named set of text substitutions in files under src/turntable/."""

    name: str
    description: str
    edits: tuple[tuple[str, str, str, int], ...]  # (file, old, new, expected count)
    tests: tuple[str, ...] = OWN_TESTS  # test files (under tests/) that must kill it
    keyword: str = ""  # pytest -k expression; "" runs every test of those files


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
            (
                "_conserved.py",
                "(k * z0[..., 5] + z0[..., 2]) / k",
                "(k * z0[..., 5] - z0[..., 2]) / k",
                1,
            ),
            (
                "solution.py",
                "rc = w0 + 1j * v0 / k",
                "rc = w0 + 1j * complex(-v0.real, v0.imag) / k",
                1,
            ),
            (
                "_no_slip.py",
                "rc = w0 + 1j * v0 / k",
                "rc = w0 + 1j * complex(-v0.real, v0.imag) / k",
                1,
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
        (("_no_slip.py", "omega = k / (k + 1.0)", "omega = k / (k + 2.0)", 1),),
    ),
    Mutant(
        "spin-from-velocity",
        "wy = wy_c + vx / k instead of wy_c - vx / k in solve (w = r_c - i v / k)",
        (("solution.py", "m[1:, 5] = -v[:, 0] / k", "m[1:, 5] = v[:, 0] / k", 1),),
    ),
    Mutant(
        "solve-block-times",
        "solve takes the growth factor of every block of times at the first block's times",
        (
            (
                "solution.py",
                "growth = np.exp(c.lp.real * tb)",
                "growth = np.exp(c.lp.real * t[: tb.size])",
                1,
            ),
        ),
    ),
    Mutant(
        "slip-sign",
        "slip_velocity with the opposite sign of gamma x (.): u = v - gamma x w + gamma x r",
        (
            (
                "_no_slip.py",
                "z[..., 2] - z[..., 5] + z[..., 1], z[..., 3] + z[..., 4] - z[..., 0]",
                "z[..., 2] + z[..., 5] - z[..., 1], z[..., 3] - z[..., 4] + z[..., 0]",
                1,
            ),
        ),
    ),
    Mutant(
        "small-friction-sign",
        "alpha1 = sqrt(mu0/2) + mu instead of sqrt(mu0/2) - mu (small_friction_expansion)",
        (("limits.py", "Expansion(root - mu, -root - mu,", "Expansion(root + mu, -root - mu,", 1),),
    ),
    Mutant(
        "no-slip-period",
        "no-slip period 2 pi (k + 2) / k instead of 2 pi (k + 1) / k (nonholonomic_period)",
        (("limits.py", "2.0 * np.pi * (k + 1.0) / k", "2.0 * np.pi * (k + 2.0) / k", 1),),
    ),
    # The checks of the parameter study and of the claims registry: a weakened check must be
    # caught by a test that feeds it a wrong model (issue 8, gaps iii and iv).
    Mutant(
        "study-bound-pi",
        "the damping bound of study.section2_checks tested as ln N > pi instead of 2 pi",
        (("study.py", "np.all(log_n > 2.0 * np.pi)", "np.all(log_n > np.pi)", 1),),
        STUDY_TESTS,
        STUDY_KEYWORD,
    ),
    Mutant(
        "study-focus-or",
        "unstable focus of study.section2_checks: alpha2 < 0 OR alpha1 > 0",
        (
            (
                "study.py",
                "(s.alpha2 < 0.0) & (s.alpha1 > 0.0)",
                "(s.alpha2 < 0.0) | (s.alpha1 > 0.0)",
                1,
            ),
        ),
        STUDY_TESTS,
        STUDY_KEYWORD,
    ),
    Mutant(
        "study-per-turn-any",
        "growth per turn of study.section2_checks: decreasing somewhere instead of everywhere",
        (("study.py", "np.all(np.diff(per_turn) < 0.0)", "np.any(np.diff(per_turn) < 0.0)", 1),),
        STUDY_TESTS,
        STUDY_KEYWORD,
    ),
    Mutant(
        "study-peak-tolerance",
        "peak bound of study.section2_checks with a tolerance of 1e-3 instead of TOL",
        (("study.py", "float(peak.alpha1) * (1.0 + TOL)", "float(peak.alpha1) * (1.0 + 1e-3)", 1),),
        STUDY_TESTS,
        STUDY_KEYWORD,
    ),
    Mutant(
        "spiral-tolerance",
        "tolerances of the trajectory.spiral check loosened a millionfold",
        (
            (
                "claims/_checks_trajectory.py",
                '"max_growth_rate_error_rel": 1e-6,\n        "max_angular_rate_error_rel": 1e-9,',
                '"max_growth_rate_error_rel": 1.0,\n        "max_angular_rate_error_rel": 1e-3,',
                1,
            ),
        ),
        CLAIMS_TESTS,
        "spiral",
    ),
    Mutant(
        "spiral-growth-tolerance",
        "only the growth-rate tolerance of the trajectory.spiral check loosened (1e-6 -> 1)",
        (
            (
                "claims/_checks_trajectory.py",
                '"max_growth_rate_error_rel": 1e-6,',
                '"max_growth_rate_error_rel": 1.0,',
                1,
            ),
        ),
        CLAIMS_TESTS,
        "spiral",
    ),
    Mutant(
        "spiral-angular-tolerance",
        "only the angular-rate tolerance of the trajectory.spiral check loosened (1e-9 -> 1e-3)",
        (
            (
                "claims/_checks_trajectory.py",
                '"max_angular_rate_error_rel": 1e-9,',
                '"max_angular_rate_error_rel": 1e-3,',
                1,
            ),
        ),
        CLAIMS_TESTS,
        "spiral",
    ),
    Mutant(
        "focus-bound-loosened",
        "spectrum.unstable_focus accepts alpha1 > -1 instead of alpha1 > 0",
        (
            (
                "claims/_checks_stability.py",
                '"min_alpha1": {">": 0.0},',
                '"min_alpha1": {">": -1.0},',
                1,
            ),
        ),
        CLAIMS_TESTS,
        "unstable_focus",
    ),
    Mutant(
        "untwisting-per-turn-any",
        "trajectory.untwisting_slows: growth per turn decreasing somewhere instead of everywhere",
        (
            (
                "claims/_checks_trajectory.py",
                "per_turn_monotone and bool(np.all(np.diff(per_turn) < 0))",
                "per_turn_monotone and bool(np.any(np.diff(per_turn) < 0))",
                1,
            ),
        ),
        CLAIMS_TESTS,
        "untwisting_slows",
    ),
    Mutant(
        "damping-ratio-bound-half",
        "solution.damping_ratio accepts |alpha2|/beta > 1/2 instead of > 1",
        (
            (
                "claims/_checks_damping.py",
                '"min_ratio_alpha2_over_beta": {">": 1.0},',
                '"min_ratio_alpha2_over_beta": {">": 0.5},',
                1,
            ),
        ),
        CLAIMS_TESTS,
        "damping_ratio",
    ),
    Mutant(
        "kernel-dimensional-radius",
        "spectrum.kernel: slip of the dimensional equations without the radius, "
        "u = v + gamma x w - Omega gamma x r (spin Omega instead of Omega/R)",
        (
            (
                "claims/_checks_spectrum.py",
                "u = v + radius * np.cross(gamma, w) - omega * np.cross(gamma, r)",
                "u = v + np.cross(gamma, w) - omega * np.cross(gamma, r)",
                1,
            ),
        ),
        CLAIMS_TESTS,
        "kernel",
    ),
    Mutant(
        "no-slip-torque-sign",
        "the contact force of rolling without slipping turns the ball the wrong way "
        "(claims reference of intro.no_slip_motion and limit.realization)",
        (("claims/_constrained.py", "-(_J @ force) / k", "(_J @ force) / k", 1),),
        CLAIMS_TESTS,
        "no_slip_motion or realization",
    ),
    Mutant(
        "scaling-without-omega",
        "the dimensionless friction taken as mu0_dim / m instead of mu0_dim / (m Omega)",
        (
            (
                "claims/_checks_intro.py",
                "return friction / (mass * omega)",
                "return friction / mass",
                1,
            ),
        ),
        CLAIMS_TESTS,
        "scaling",
    ),
    Mutant(
        "rolling-growth-ratio",
        "sigma_g = 4 delta q / (A (k + 1 + q)) instead of (k + 2 + q) (rolling spectrum)",
        (
            (
                "_rolling_spectrum.py",
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
                "_rolling_spectrum.py",
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
                "_rolling_spectrum.py",
                "nu_c = -4.0 * d * d / (a * (q + k))",
                "nu_c = 4.0 * d * d / (a * (q + k))",
                1,
            ),
        ),
    ),
    Mutant(
        "rolling-amplitude-sign",
        "A_g = (v0 + lambda_c r0) / (lambda_g - lambda_c) instead of v0 - lambda_c r0 (rolling)",
        (("_rolling_solution.py", "(v0 - lc * r0) / d", "(v0 + lc * r0) / d", 1),),
    ),
    Mutant(
        "rolling-constraint-sign",
        "w = r - i v instead of w = r + i v in the rolling solution",
        (("_rolling_solution.py", "w = amp + 1j * v", "w = amp - 1j * v", 1),),
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
        "(k u) instead of ((k + 1) u) in the slip of the slipping mode: k alpha1 instead of "
        "(k + 1) alpha1 in equal_power_delta and own_spin_power_delta",
        (
            (
                "_rolling_match.py",
                "num = np.hypot((k + 1.0) * alpha1, y)",
                "num = np.hypot(k * alpha1, y)",
                2,
            ),
        ),
    ),
    Mutant(
        "equal-power-own-spin",
        "comparison (b) charges the rolling torque on the slipping ball's own spin "
        "-i lambda_+ r / k instead of the rolling spin r + i v on the same path",
        (
            (
                "_rolling_match.py",
                "den = k * np.hypot(1.0 - beta, alpha1)",
                "den = beta * np.hypot(1.0, alpha1 / beta)",
                1,
            ),
        ),
    ),
    Mutant(
        "equal-power-rolling-spin-sign",
        "the ball rolling along the slipping path spins with w = r - i v: |1 - i lambda_+| "
        "instead of |1 + i lambda_+| in equal_power_delta",
        (
            (
                "_rolling_match.py",
                "den = k * np.hypot(1.0 - beta, alpha1)",
                "den = k * np.hypot(1.0 + beta, alpha1)",
                1,
            ),
        ),
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
    # The rolling model through the claims registry: comparison.rolling_resistance must
    # notice a wrong rolling model on its own (its references and the 3-D integration).
    Mutant(
        "rolling-claim-torque-sign",
        "the rolling-resistance moment drives the spin (+delta w_h) in the 3-D equations "
        "(killed by the comparison.rolling_resistance claim: solve against the integration)",
        (
            (
                "rolling.py",
                "return -delta * np.array([w[0], w[1], 0.0])",
                "return delta * np.array([w[0], w[1], 0.0])",
                1,
            ),
        ),
        CLAIMS_TESTS,
        ROLLING_CLAIM,
    ),
    Mutant(
        "rolling-claim-centre-decay",
        "sigma_c = -(delta + p) / (2 (k + 2)) instead of / (2 (k + 1)) (killed by the "
        "comparison.rolling_resistance claim: spectrum against 50 digits)",
        (
            (
                "_rolling_spectrum.py",
                "sigma_c = -(delta + p) / (2.0 * (k + 1.0))",
                "sigma_c = -(delta + p) / (2.0 * (k + 2.0))",
                1,
            ),
        ),
        CLAIMS_TESTS,
        ROLLING_CLAIM,
    ),
    Mutant(
        "limit-fit-log-base",
        "limit_error_fit regresses ln(error) on log10(mu0): the order off by a factor ln 10",
        (
            (
                "limits.py",
                "np.polyfit(np.log(mu0), np.log(error), 1)",
                "np.polyfit(np.log10(mu0), np.log(error), 1)",
                1,
            ),
        ),
    ),
    Mutant(
        "much-faster-without-factor",
        "comparison.rolling_resistance confirmed when slipping is merely faster everywhere "
        "(ratio > 1), with no factor for 'much'",
        (
            (
                "claims/_ratios.py",
                "if np.all(values >= factor):",
                "if np.all(values > 1.0):",
                1,
            ),
        ),
        CLAIMS_TESTS,
        "much_faster or factors",
    ),
    Mutant(
        "much-faster-failed-one-sided",
        "comparison.rolling_resistance failed whenever slipping is never much faster, "
        "although rolling may be (the other reading of 'in this case')",
        (
            (
                "claims/_ratios.py",
                "if np.all((values > 1.0 / factor) & (values < factor)):",
                "if np.all(values < factor):",
                1,
            ),
        ),
        CLAIMS_TESTS,
        "much_faster or factors",
    ),
    Mutant(
        "rolling-claim-equal-power-own-spin",
        "comparison (b) charged on the slipping ball's own spin (killed by the "
        "comparison.rolling_resistance claim: delta_P against the eigenvector reference)",
        (
            (
                "_rolling_match.py",
                "den = k * np.hypot(1.0 - beta, alpha1)",
                "den = beta * np.hypot(1.0, alpha1 / beta)",
                1,
            ),
        ),
        CLAIMS_TESTS,
        ROLLING_CLAIM,
    ),
    Mutant(
        "fit-coefficient-column",
        "the column d r / d ln c of the fit's Jacobian twice too large (standard errors halved)",
        (("fit/parameters.py", "((up - down) / (2.0 * LOG_STEP))", "((up - down) / LOG_STEP)", 1),),
        FIT_TESTS,
    ),
    Mutant(
        "fit-no-nuisance",
        "standard error of a parameter without projecting out the others (the initial state)",
        (
            (
                "fit/parameters.py",
                "return j_i - rest @ coef",
                "return j_i",
                1,
            ),
        ),
        FIT_TESTS,
    ),
    Mutant(
        "fit-no-drift",
        "the standard errors ignore errors that drift slowly (the slow part always none)",
        (
            (
                "fit/parameters.py",
                "return (w, s, a) if z > DRIFT_Z else (w, 0.0, a)",
                "return (w, 0.0, a)",
                1,
            ),
        ),
        ("test_fit.py",),
        "drifting",
    ),
    Mutant(
        "fit-drift-not-absorbed",
        "the slow part of the errors fitted as if the fit absorbed none of it",
        (
            (
                "fit/parameters.py",
                "- lag_sums(cross + np.conj(cross) - projected)",
                "- 0.0 * lag_sums(cross + np.conj(cross) - projected)",
                1,
            ),
        ),
        ("test_fit.py",),
        "drifting",
    ),
    Mutant(
        "fit-clock",
        "the fit forgets Omega: tau = t - t0 instead of Omega (t - t0)",
        (
            (
                "fit/lsq.py",
                "return setup.omega * t, xy / setup.radius",
                "return t, xy / setup.radius",
                1,
            ),
        ),
        FIT_TESTS,
    ),
    Mutant(
        "fit-delta-units",
        "delta_dim = delta m R Omega instead of delta m R^2 Omega",
        (
            (
                "fit/io.py",
                '(1.0 if model == "slipping" else setup.radius**2)',
                '(1.0 if model == "slipping" else setup.radius)',
                1,
            ),
        ),
        FIT_TESTS,
    ),
    Mutant(
        "fit-expected-aic",
        "expected AIC difference without the penalty of the two extra parameters",
        (("fit/_predict.py", "d = 2.0 * q + 2.0 * k_s", "d = q + 2.0 * k_s", 1),),
        FIT_TESTS,
    ),
    Mutant(
        "realization-map-sign",
        "the map that keeps (r, v) sets w = -r + J v (off u = 0) instead of r + J v",
        (
            (
                "claims/_constrained.py",
                "out[PARTS[solved]] = -np.linalg.solve(slip[:, PARTS[solved]], rest)",
                "out[PARTS[solved]] = -np.linalg.solve(slip[:, PARTS[solved]], rest)\n"
                "    out[4:6, 0:2] *= -1.0",
                1,
            ),
        ),
        tests=PRINTED_TESTS,
    ),
    Mutant(
        "realization-reduction",
        "the other maps' distance: the largest over k instead of the least its record names",
        (
            (
                "claims/_checks_realization.py",
                "others_min, free_min = min(others_per_k), min(free_per_k)",
                "others_min, free_min = max(others_per_k), min(free_per_k)",
                1,
            ),
        ),
        tests=PRINTED_TESTS,
    ),
    Mutant(
        "damping-parameter",
        "N at the first of mu0_small instead of the last its record names",
        (
            (
                "claims/_checks_damping.py",
                "n_smallest = float(np.exp(tt.log_damping_ratio(small[-1], k0)))",
                "n_smallest = float(np.exp(tt.log_damping_ratio(small[0], k0)))",
                1,
            ),
        ),
        tests=PRINTED_TESTS,
    ),
    Mutant(
        "untwisting-parameter",
        "alpha1 around the peak at the first k instead of k_paper",
        (
            (
                "claims/_checks_trajectory.py",
                '"alpha1_around_peak_k_paper": list(_alpha1_around_peak(k0)),',
                '"alpha1_around_peak_k_paper": list(_alpha1_around_peak(p["k_values"][0])),',
                1,
            ),
        ),
        tests=PRINTED_TESTS,
    ),
]


def _prepare(tmp: Path, names: tuple[str, ...]) -> list[str]:
    """Copy src/, the tests ``names`` with the helpers they import, config/, workflow/,
    paper/paper.typ and pyproject.toml into tmp; return the test paths."""
    shutil.copytree(
        ROOT / "src", tmp / "src", ignore=shutil.ignore_patterns("__pycache__", "*.egg-info")
    )
    for folder in ("config", "workflow"):  # read by some tests (the claims configuration)
        shutil.copytree(ROOT / folder, tmp / folder)
    (tmp / "tests").mkdir()
    for helper in (ROOT / "tests").glob("*.py"):  # conftest.py, reference.py, ...
        if not helper.name.startswith("test_"):
            shutil.copy2(helper, tmp / "tests" / helper.name)
    tests = []
    for name in names:
        shutil.copy2(ROOT / "tests" / name, tmp / "tests" / name)
        tests.append(f"tests/{name}")
    shutil.copy2(ROOT / "pyproject.toml", tmp / "pyproject.toml")
    (tmp / "paper").mkdir()
    shutil.copy2(ROOT / "paper" / "paper.typ", tmp / "paper" / "paper.typ")  # what it prints
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


def _run(tmp: Path, tests: list[str], fast: bool, keyword: str) -> tuple[int, list[str], float]:
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
    cmd = [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q", "-n", "2", "-m", ""]
    cmd += ["--junitxml", str(report), *(["-x"] if fast else []), *tests]
    cmd += ["-k", keyword] if keyword else []
    start = time.perf_counter()
    proc = subprocess.run(cmd, env=env, cwd=tmp, capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - start
    failed = []
    if report.exists():
        for case in ET.parse(report).getroot().iter("testcase"):
            if case.find("failure") is not None or case.find("error") is not None:
                failed.append(f"{case.get('classname')}::{case.get('name')}")
        report.unlink()
    # With -x, pytest-xdist ends an interrupted run with exit code 2 after a failure.
    stopped = fast and proc.returncode == 2 and bool(failed)
    if (proc.returncode not in (0, 1) and not stopped) or (proc.returncode == 1 and not failed):
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
        for i, (names, keyword) in enumerate(dict.fromkeys((m.tests, m.keyword) for m in mutants)):
            tmp = base_dir / f"baseline-{i}"
            tmp.mkdir()
            tests = _prepare(tmp, names)
            code, failed, seconds = _run(tmp, tests, args.fast, keyword)
            selection = ", ".join(names) + (f" -k {keyword!r}" if keyword else "")
            print(f"baseline (no mutation; {selection}): {len(failed)} failed, {seconds:.1f} s")
            if code != 0:
                print(_summarise(failed))
                print("the unmutated code must pass its tests first")
                return 1
            shutil.rmtree(tmp)

        survivors = []
        for mutant in mutants:
            tmp = base_dir / mutant.name
            tmp.mkdir()
            tests = _prepare(tmp, mutant.tests)
            _apply(tmp, mutant)
            code, failed, seconds = _run(tmp, tests, args.fast, mutant.keyword)
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
