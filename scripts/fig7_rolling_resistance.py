# %%
"""Figure 7: slipping with viscous friction against rolling with rolling resistance.

Caption: top, path of the centre of the slipping ball (coefficient mu0, left) and of the
rolling ball (coefficient delta matched to mu0 by the configured comparison, middle), both
from the same state on the no-slip constraint, on one scale; dashed: each spiral's centre
over time (fixed for slipping, drifting into the turntable's axis for rolling); right:
distance of each centre from the axis against time. Bottom, against mu0, for slipping
(black) and for rolling under equal dissipated power on the same path of the centre
(each ball with its own spin; wide, under the black curve where they coincide), the
matching the verdict rests on, and under equal coefficients, delta = mu0, a sensitivity
(dotted): left, log growth of the spiral per turn; middle, its growth rate per unit time;
right, the ratios slipping over rolling, per turn under both, per unit time under equal
power (dashed), with the factor that "much faster" means in the claims registry
(much_faster_factor) either way.
"""

# %%
import numpy as np

import turntable
from _style import DOUBLE, save, setup, subplots
from turntable import claims, rolling

setup(snakemake)
p = snakemake.params
z0 = turntable.no_slip_state(p.state, p.k)
delta = float(rolling.matched_delta(p.mu0, p.k, p.comparison))
t = np.linspace(*p.t_span, p.n_points)
fig, axes = subplots(2, 3, (DOUBLE, 5.0), (0.5, 0.12, 0.42, 0.45), (0.55, 0.6))
(ax_s, ax_r, ax_c), (ax_g, ax_t, ax_q) = axes

# %%
slip = turntable.solve(z0, t, p.mu0, p.k)
centre_s = np.broadcast_to(turntable.spiral_centre(z0, p.k), (t.size, 2))
roll = rolling.solve(z0, t, delta, p.k)
centre_r = rolling.spiral_centre(z0, t, delta, p.k)
name = p.comparison.replace("_", " ")
runs = [
    (ax_s, slip, centre_s, "C0", rf"slipping, $\mu_0 = {p.mu0:g}$, $k = {p.k:g}$", "slipping"),
    (
        ax_r,
        roll,
        centre_r,
        "C3",
        rf"rolling, $\delta = {delta:.3g}$ ({name}), $k = {p.k:g}$",
        "rolling",
    ),
]
# Both paths on the same scale, so that the panels have the same size and can be compared.
xy = np.concatenate([slip[:, :2], roll[:, :2]])
pad = 0.05 * np.ptp(xy, axis=0).max()
lims = [(lo - pad, hi + pad) for lo, hi in zip(xy.min(axis=0), xy.max(axis=0), strict=True)]
for ax, z, c, color, title, short in runs:
    ax.plot(z[:, 0], z[:, 1], color=color, lw=0.8)
    ax.plot(c[:, 0], c[:, 1], "k--", lw=1.0, label="spiral centre over time")
    ax.plot(*c[-1], "ko", ms=4, label=f"spiral centre at $t\\Omega = {t[-1]:g}$")
    ax.plot(*z0[:2], "o", mfc="w", mec="k", ms=4, label="start")
    ax.plot(0, 0, "k+", ms=8, label="axis")
    ax.set(aspect="equal", xlim=lims[0], ylim=lims[1], xlabel="$x/R$", ylabel="$y/R$")
    ax.set_title(title, fontsize=7)
    ax_c.plot(t, np.hypot(*c.T), color=color, label=short)
handles, labels = ax_r.get_legend_handles_labels()
fig.legend(handles, labels, loc="upper center", ncols=4, fontsize=7, frameon=False)
ax_c.set(xlabel=r"time $t\Omega$", ylabel="centre's distance from the axis $/R$", ylim=(0, None))
ax_c.legend(fontsize=6.5, loc="lower left")
ax_c.set_title(rf"$k = {p.k:g}$", fontsize=7)

# %%
mu0 = np.logspace(*np.log10(p.mu0_range), p.n_grid)
per_turn = turntable.log_growth_per_turn(mu0, p.k)
per_time = turntable.spectrum(mu0, p.k).alpha1
# Equal power, the matching the verdict rests on, wide and under the thin black slipping curve, so
# that it shows where the two coincide (large mu0); equal coefficients, a sensitivity, dotted.
styles = {
    "equal_power": {"color": "C2", "lw": 3.0, "alpha": 0.6, "label": "equal power"},
    "equal_coefficient": {"color": "C1", "lw": 1.2, "ls": ":", "label": r"$\delta = \mu_0$"},
}
ratios = []
for comparison, style in styles.items():
    matched = rolling.matched_delta(mu0, p.k, comparison)
    turn_r = rolling.log_growth_per_turn(matched, p.k)
    time_r = rolling.growth_rate(matched, p.k)
    ax_g.loglog(mu0, turn_r, **{**style, "label": f"rolling, {style['label']}"})
    ax_t.loglog(mu0, time_r, **style)
    ax_q.loglog(mu0, per_turn / turn_r, **{**style, "label": f"per turn, {style['label']}"})
    ratios += [per_turn / turn_r]
    if comparison == "equal_power":
        ratios += [per_time / time_r]
        ax_q.loglog(mu0, per_time / time_r, **{**style, "lw": 1.2, "alpha": 1.0, "ls": "--",
                                                "label": "per unit time, equal power"})  # fmt: skip
ax_g.loglog(mu0, per_turn, "k", lw=1.0, label="slipping")
ax_t.loglog(mu0, per_time, "k", lw=1.0)
factor = claims.resolve_params(p.claims)["much_faster_factor"]
for level in (factor, 1.0 / factor):
    ax_q.axhline(level, color="0.6", lw=0.8)
ax_q.axhline(1.0, color="0.3", lw=0.5)
ax_q.plot([], [], color="0.6", lw=0.8, label=f"factor {factor:g} either way")
values = np.concatenate(ratios)
ax_q.set_ylim(min(values.min(), 1 / factor) / 3, values.max() * 3)
friction = r"friction $\mu_0$ (units of $m\Omega$)"
ax_g.set(xlabel=friction, ylabel="log growth per turn")
ax_t.set(xlabel=friction, ylabel=r"growth rate per unit time $/\Omega$")
ax_q.set(xlabel=friction, ylabel="slipping / rolling")
ax_g.legend(fontsize=6.5, loc="lower left")
ax_q.legend(fontsize=6.5, loc="upper right")
for ax, title in ((ax_g, "growth per turn"), (ax_t, "growth per unit time"), (ax_q, "ratios")):
    ax.set_title(rf"{title}, $k = {p.k:g}$", fontsize=7)
save(fig, snakemake)
