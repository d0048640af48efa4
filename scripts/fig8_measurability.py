# %%
"""Figure 8: what a camera can measure on a ball slipping on a turntable.

Caption: (a) relative standard error of mu0 reachable with the configured camera (section
film) against mu0, and of delta for a ball rolling without slipping against delta (the
Cramer-Rao bound of turntable.fit.predicted_stderr, the initial state unknown); solid where
it is below the configured reliable_relative_error, where fits reach it, dotted and grey
beyond, where the fit is no longer locally linear and the estimates scatter more. (b) rms
distance per coordinate between the slipping ball's path and the closest rolling path,
over the tracking noise, and the probability that AICc selects the slipping model. Shaded:
the mu0 where that probability is below the configured level, where the two mechanisms
cannot be told apart. Also writes the numbers to results/film/measurability.json.
"""

# %%
import json

import numpy as np

from _style import DOUBLE, save, setup, subplots
from turntable import film, fit
from turntable._atomic import write_text

setup(snakemake)
p = snakemake.params
rig = film.rig_from_config(p.film)
mu0 = np.geomspace(*p.mu0_range, p.n_grid)
table = fit.measurability(mu0, rig.state0, rig.setup, rig.camera)
limit = fit.indistinguishable_above(table, p.selection_probability)
numbers = fit.measurability_json(
    table, p.selection_probability, rig, reliable_level=p.reliable_relative_error
)
write_text(snakemake.output.json, json.dumps(numbers, indent=1))


def curve(ax, x, rel, color, style, label):
    """rel against x: solid where rel is below the reliable level, dotted and grey beyond.

    The crossings with the level (interpolated in log-log) join the two parts.
    """
    level = p.reliable_relative_error
    lx, lr = np.log(x), np.log(rel)
    crossings = [
        lx[i] + (np.log(level) - lr[i]) / (lr[i + 1] - lr[i]) * (lx[i + 1] - lx[i])
        for i in range(x.size - 1)
        if (lr[i] - np.log(level)) * (lr[i + 1] - np.log(level)) < 0
    ]
    fine = np.sort(np.concatenate([lx, crossings]))
    xs, rs = np.exp(fine), np.exp(np.interp(fine, lx, lr))
    below, above = rs <= level * (1 + 1e-9), rs >= level * (1 - 1e-9)
    ax.loglog(xs, np.where(below, rs, np.nan), color=color, ls=style, label=label)
    ax.loglog(xs, np.where(above, rs, np.nan), color="0.35", ls=":", lw=1.4)


# %%
fig, ((ax_se, ax_d),) = subplots(1, 2, (DOUBLE, 3.0), (0.6, 0.55, 0.45, 0.3), (0.9, 0.5))
curve(ax_se, mu0, table.mu0_stderr / mu0, "C0", "-", r"slipping: $\sigma(\mu_0)/\mu_0$")
curve(ax_se, mu0, table.delta_stderr / mu0, "C3", "--", r"rolling: $\sigma(\delta)/\delta$")
ax_se.axhline(p.reliable_relative_error, color="0.6", lw=0.6, ls="-")
ax_se.text(
    mu0[0],
    p.reliable_relative_error * 1.15,
    f"{p.reliable_relative_error:g}: reached by fits below",
    color="0.45",
    fontsize=6.5,
)
ax_se.plot([], [], color="0.35", ls=":", lw=1.4, label="not reached by fits")
ax_se.set(xlabel=r"$\mu_0$ or $\delta$", ylabel="relative standard error")
ax_d.loglog(
    mu0,
    table.rms_distance / rig.camera.noise,
    "k",
    label="closest rolling path:\nrms distance / noise",
)
ax_d.set(xlabel=r"$\mu_0$", ylabel="rms distance / noise")
ax_p = ax_d.twinx()
ax_p.semilogx(mu0, table.selection_probability, "C2", label="P(AICc selects slipping)")
ax_p.axhline(p.selection_probability, color="C2", ls=":", lw=0.8)
ax_p.text(
    mu0[0],
    p.selection_probability - 0.01,
    f"{p.selection_probability:g}",
    color="C2",
    va="top",
    fontsize=7,
)
ax_p.set(ylim=(0, 1.02), ylabel="P(AICc selects slipping)")
ax_p.yaxis.label.set_color("C2")
# the limit is a value of mu0 (a slipping ball filmed): shaded in (b) only, whose axis is mu0
ax_d.axvspan(limit, mu0[-1], color="0.85", zorder=0, lw=0)
ax_d.axvline(limit, color="0.5", lw=0.8)
ax_d.text(
    mu0[-1] / 1.3,
    0.62,
    f"cannot be\ntold apart:\n$\\mu_0 > {limit:.3g}$",
    transform=ax_d.get_xaxis_transform(),
    va="bottom",
    ha="right",
    fontsize=7,
)
# headroom above the curves for the legend
ax_se.set_ylim(top=ax_se.get_ylim()[1] * 1e2)
ax_se.legend(fontsize=7, loc="upper left")
lines = ax_d.get_legend_handles_labels()
twin = ax_p.get_legend_handles_labels()
ax_d.legend(lines[0] + twin[0], lines[1] + twin[1], fontsize=7, loc="lower left")
cam = rig.camera
fig.suptitle(
    f"ball of radius {rig.setup.radius * 1e3:g} mm at {rig.setup.omega:.3g} rad/s; "
    f"{cam.fps:g} frames/s, {cam.noise * 1e3:g} mm noise, {cam.duration:g} s",
    fontsize=8,
)
save(fig, snakemake)
