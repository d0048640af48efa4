r"""From a filmed ball to its friction: fit both friction models, and design the experiment.

Two mechanisms can make a ball's centre spiral outwards on a turntable:

``slipping``
    the paper's model, viscous friction :math:`F = -\mu_0 u` at the contact point
    (`turntable.solve`, coefficient :math:`\mu_0 = \mu_{0,\text{dim}} / (m \Omega)`);
``rolling_resistance``
    rolling without slipping against a resistance torque :math:`-\delta \omega`
    (`turntable.rolling.solve`, coefficient :math:`\delta = \delta_\text{dim} / (m R^2 \Omega)`).

`fit_model` fits one of them to a `turntable.film.Film` (tracked positions in the lab frame,
SI units) by nonlinear least squares (`scipy.optimize.least_squares`) on the exact
closed-form solution, in the paper's units: :math:`\tau = \Omega (t - t_0)`,
:math:`r = (\text{position} - \text{axis}) / R`.
The parameters are the state at the first frame t0 and the logarithm of the coefficient
(which keeps it positive): 6 + 1 for slipping, and 4 + 1 for rolling, whose state is
parametrised on the no-slip constraint by (x, y, vx, vy) (`turntable.rolling.state_on_constraint`).
Optionally also :math:`s = \ln(\Omega / \Omega_\text{given})` (``fit_omega``: the turntable's
rate is not known exactly) and, for the rolling model, the position a of the axis
(``fit_axis``); the slipping motion does not depend on the axis at all (a shift of the
position with the same shift of the spin is again a solution, the plane of equilibria
(2.3)), so there the axis is neither needed nor identifiable.  With :math:`\Omega` free,
:math:`\tau = \Omega_\text{given} e^s (t - t_0)` and :math:`dr / ds = \tau v(\tau)`: both
models' rates scale with :math:`\Omega`, and the ratio of growth to turning
(:math:`\alpha_1 / \beta`, or :math:`\operatorname{Re} \lambda_g / \operatorname{Im} \lambda_g`)
fixes the coefficient alone, so :math:`\Omega` is identifiable from a film of a turn or more.

The modules, one concern each: ``models`` (the models' positions and parameter counts,
shared with ``simulate``, the synthetic films), ``parameters`` (the parameter vector and the
Jacobian), ``start`` (start values), ``results`` (what a fit returns; AICc and whiteness),
``lsq`` (the fits), ``response`` (how a coefficient follows a change of its film),
``diagnose`` (consistency of :math:`\Omega` and the axis, problems), `io` (the JSON of ``turntable
fit`` and reading it back), ``design`` (predicted errors, distinguishability,
measurability) and ``plot`` (drawing a fit; matplotlib is imported there only).  Their public
names are importable from `turntable.fit`.
"""

from turntable.fit.design import (
    Distinguishability,
    Measurability,
    distinguishability,
    indistinguishable_above,
    measurability,
    measurability_json,
    predicted_stderr,
    reliable_range,
)
from turntable.fit.diagnose import (
    CONSISTENCY_Z,
    LINEAR_RELATIVE_ERROR,
    MAX_FRAME_STEP,
    Consistency,
    checked_selection,
    consistency,
    frame_step,
    problems,
    undescribed,
)
from turntable.fit.io import (
    fitted_coefficient,
    fitted_positions,
    result_json,
    setup_from_json,
)
from turntable.fit.lsq import (
    EXACT_FIT,
    OMEGA_FACTOR,
    Z95_ONE_SIDED,
    fit_film,
    fit_model,
)
from turntable.fit.models import (
    BOUNDS,
    COEFFICIENT,
    MIN_DOF,
    MODELS,
    N_STATE,
    min_frames,
    n_parameters,
    positions,
)
from turntable.fit.parameters import (
    LOG_STEP,
)
from turntable.fit.results import (
    DECISIVE,
    NOISE_FACTOR,
    WHITENESS_Z,
    Z95,
    FilmFit,
    ModelFit,
    aic,
    aicc,
    frame_noise,
    whiteness,
)
from turntable.fit.simulate import (
    simulate_film,
    synthetic_header,
)
from turntable.fit.start import (
    GRID_PER_DECADE,
    START_FRAMES,
    START_STEP,
    start_values,
)

__all__ = [
    "BOUNDS",
    "COEFFICIENT",
    "CONSISTENCY_Z",
    "DECISIVE",
    "EXACT_FIT",
    "GRID_PER_DECADE",
    "LINEAR_RELATIVE_ERROR",
    "LOG_STEP",
    "MAX_FRAME_STEP",
    "MIN_DOF",
    "MODELS",
    "NOISE_FACTOR",
    "N_STATE",
    "OMEGA_FACTOR",
    "START_FRAMES",
    "START_STEP",
    "WHITENESS_Z",
    "Z95",
    "Z95_ONE_SIDED",
    "Consistency",
    "Distinguishability",
    "FilmFit",
    "Measurability",
    "ModelFit",
    "aic",
    "aicc",
    "checked_selection",
    "consistency",
    "distinguishability",
    "fit_film",
    "fit_model",
    "fitted_coefficient",
    "fitted_positions",
    "frame_noise",
    "frame_step",
    "indistinguishable_above",
    "measurability",
    "measurability_json",
    "min_frames",
    "n_parameters",
    "positions",
    "predicted_stderr",
    "problems",
    "reliable_range",
    "result_json",
    "setup_from_json",
    "simulate_film",
    "start_values",
    "synthetic_header",
    "undescribed",
    "whiteness",
]
