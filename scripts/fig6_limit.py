# %%
"""Figure 6: the no-slip limit mu0 -> infinity of Section 3.

Caption: (a) paths of the centre over one period 2 pi (k + 1)/k of the no-slip motion for
growing mu0 (initial state x = y = 1, v = 0, wx = 0, wy = 1 by default), and the no-slip
circle (3.3) (grey band, under the coloured paths). (b) Largest distance between the
slipping and the no-slip paths on [0, T] against mu0, with its least-squares power law: the
fit of the claim limit.convergence for the paper's ball (turntable.limit_error_fit with the
claims parameters t_limit, mu0_limit, state_fig4 and k_paper), whose order the article
quotes from results/claims.json. (c) The initial layer: speed of the centre
for an initial state off the no-slip constraint, against time on a log axis, and the no-slip
speed (grey band). (d) Slip speed |u| in the same runs: it decays on the time scale
k/(mu0 (k + 1)). One colour per mu0 in all panels.
"""

# %%
import numpy as np

import turntable
from _style import DOUBLE, save, setup, subplots
from turntable import claims

setup(snakemake)
p = snakemake.params
t = np.linspace(0.0, float(turntable.nonholonomic_period(p.k)), p.n_points)
t_layer = np.geomspace(*p.layer_t_span, p.n_points)
fig, axes = subplots(2, 2, (DOUBLE, 5.0), (0.55, 0.1, 0.4, 0.22), (1.0, 0.65))
(ax_a, ax_b), (ax_c, ax_d) = axes
# One colour per mu0 in every panel; the no-slip curves are wide grey bands underneath.
colour = {m: f"C{i}" for i, m in enumerate(sorted({*p.mu0_trajectories, *p.mu0_layer}))}
no_slip = {"color": "0.7", "lw": 3.5, "zorder": 1, "label": "no slip"}

# %% (a) paths and (b) position error over one no-slip period
for mu0 in p.mu0_trajectories:
    z = turntable.solve(p.state, t, mu0, p.k)
    ax_a.plot(*z[:, :2].T, color=colour[mu0], lw=1.0, label=rf"$\mu_0 = {mu0:g}$")
ax_a.plot(*turntable.nonholonomic(p.state, t, p.k)[:, :2].T, **no_slip)
ax_a.plot(*turntable.spiral_centre(p.state, p.k), "ko", ms=4)
ax_a.plot(*p.state[:2], "o", mfc="w", mec="k", ms=4)
ax_a.set(aspect="equal", xlabel="$x/R$", ylabel="$y/R$")
ax_a.set_title(rf"(a) one no-slip period, $t\Omega \leq {t[-1]:.2f}$")
ax_a.legend(loc="center left", bbox_to_anchor=(1.0, 0.5))
# (b) is the fit of the claim limit.convergence: the same function, the same parameters.
c = claims.resolve_params(p.claims)
fit = turntable.limit_error_fit(c["state_fig4"], c["t_limit"], c["mu0_limit"], c["k_paper"])
ax_b.loglog(fit.mu0, fit.error, "o", color="k", ms=3, label="computed")
line = np.geomspace(fit.mu0[0], fit.mu0[-1], 50)
ax_b.loglog(
    line, fit.prefactor * line**fit.order, "k-", lw=0.7, label=f"fit: order {fit.order:.4g}"
)
ax_b.set(
    xlabel=r"friction $\mu_0$ (units of $m\Omega$)",
    title=rf"(b) largest position error, $k = {c['k_paper']:g}$",
)
ax_b.set_ylabel(rf"$\max |\mathbf{{r}} - \mathbf{{r}}_{{\rm ns}}|/R$ on $[0, {c['t_limit']:g}]$")
ax_b.legend()
print(f"fitted order of the position error: {fit.order:.12g}")

# %% (c) speed and (d) slip speed in the initial layer
v_ns = np.hypot(*turntable.nonholonomic(p.layer_state, t_layer, p.k)[:, 2:4].T)
for mu0 in p.mu0_layer:
    z = turntable.solve(p.layer_state, t_layer, mu0, p.k)
    style = {"color": colour[mu0], "label": rf"$\mu_0 = {mu0:g}$"}
    ax_c.plot(t_layer, np.hypot(*z[:, 2:4].T), **style)
    ax_d.loglog(t_layer, np.hypot(*turntable.slip_velocity(z).T), **style)
ax_c.plot(t_layer, v_ns, **no_slip)
ax_c.set(xscale="log", ylabel=r"speed $|\mathbf{v}|/(R\Omega)$", title="(c) initial layer")
ax_d.set(ylabel=r"slip speed $|\mathbf{u}|/(R\Omega)$", title="(d) slip in the initial layer")
for ax in (ax_c, ax_d):
    ax.set_xlabel(r"time $t\Omega$")
    ax.legend()
save(fig, snakemake)
