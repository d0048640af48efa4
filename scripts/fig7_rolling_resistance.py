# %%
"""Figure 7: slipping with viscous friction against rolling with rolling resistance.

Caption: top, path of the centre of the slipping ball (coefficient mu0, left) and of the
rolling ball (coefficient delta matched to mu0 by the configured comparison, right), both
from the same state on the no-slip constraint; dashed: each spiral's centre over time (fixed
for slipping, drifting into the turntable's axis for rolling). Bottom left: distance of each
centre from the axis against time. Bottom right: log growth of the spiral per turn against
mu0, slipping and rolling under the comparisons (a) delta = mu0, (b) equal dissipated power,
(c) equal decay of the non-growing part.
"""

# %%
import numpy as np

import turntable
from _style import DOUBLE, save, setup, subplots
from turntable import rolling

setup(snakemake)
p = snakemake.params
z0 = turntable.no_slip_state(p.state, p.k)
delta = float(rolling.matched_delta(p.mu0, p.k, p.comparison))
t = np.linspace(*p.t_span, p.n_points)
fig, axes = subplots(2, 2, (DOUBLE, 5.8), (0.55, 0.15, 0.45, 0.45), (0.6, 0.6))
(ax_s, ax_r), (ax_c, ax_g) = axes

# %%
slip = turntable.solve(z0, t, p.mu0, p.k)
centre_s = np.broadcast_to(turntable.spiral_centre(z0, p.k), (t.size, 2))
roll = rolling.solve(z0, t, delta, p.k)
centre_r = rolling.spiral_centre(z0, t, delta, p.k)
runs = [
    (ax_s, slip, centre_s, "C0", rf"slipping, $\mu_0 = {p.mu0:g}$"),
    (
        ax_r,
        roll,
        centre_r,
        "C3",
        rf"rolling, $\delta = {delta:.4g}$ ({p.comparison.replace('_', ' ')})",
    ),
]
# Both paths on the same scale, so that the panels have the same size and can be compared.
xy = np.concatenate([slip[:, :2], roll[:, :2]])
pad = 0.05 * np.ptp(xy, axis=0).max()
lims = [(lo - pad, hi + pad) for lo, hi in zip(xy.min(axis=0), xy.max(axis=0), strict=True)]
for ax, z, c, color, title in runs:
    ax.plot(z[:, 0], z[:, 1], color=color, lw=0.8)
    ax.plot(c[:, 0], c[:, 1], "k--", lw=1.0, label="spiral centre over time")
    ax.plot(*c[-1], "ko", ms=4, label=f"spiral centre at $t\\Omega = {t[-1]:g}$")
    ax.plot(*z0[:2], "o", mfc="w", mec="k", ms=4, label="$z(0)$")
    ax.plot(0, 0, "k+", ms=8, label="axis")
    ax.set(aspect="equal", xlim=lims[0], ylim=lims[1], xlabel="$x/R$", ylabel="$y/R$")
    ax.set_title(title)
    ax_c.plot(t, np.hypot(*c.T), color=color, label=title)
handles, labels = ax_r.get_legend_handles_labels()
fig.legend(handles, labels, loc="upper center", ncols=4, fontsize=6, frameon=False)
ax_c.set(
    xlabel=r"time $t\Omega$", ylabel="distance of the centre from the axis $/R$", ylim=(0, None)
)
ax_c.legend(fontsize=6)

# %%
mu0 = np.logspace(*np.log10(p.mu0_range), p.n_grid)
ax_g.loglog(mu0, turntable.log_growth_per_turn(mu0, p.k), "k", lw=1.5, label="slipping")
styles = {
    "equal_coefficient": ("C1", "-", r"(a) $\delta = \mu_0$"),
    "equal_power": ("C2", "--", "(b) equal power"),
    "equal_decay": ("C4", ":", "(c) equal decay"),
}
for name, (color, ls, label) in styles.items():
    g = rolling.log_growth_per_turn(rolling.matched_delta(mu0, p.k, name), p.k)
    ax_g.loglog(mu0, g, color=color, ls=ls, label=f"rolling, {label}")
ax_g.set(xlabel=r"$\mu_0$", ylabel="log growth per turn", title=rf"$k = {p.k:g}$")
ax_g.legend(fontsize=6, loc="lower left")
save(fig, snakemake)
