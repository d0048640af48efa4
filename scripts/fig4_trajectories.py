# %%
"""Figure 4: trajectories of the centre of the ball for several friction coefficients.

Caption: path (x(t), y(t)) of the centre for each mu0 of the configuration (initial state
x = y = 1, v = 0, wx = 0, wy = 1, k = 2/5 by default); open circle: the start; heavy dot: the
spiral centre (x0, y0) of (2.8). Last panel: distance from the spiral centre against time
on a log scale, which grows like e^(alpha1 t) once the transient has died out.
"""

# %%
import numpy as np

import turntable
from _style import DOUBLE, save, setup, subplots

setup(snakemake)
p = snakemake.params
centre = turntable.spiral_centre(p.state, p.k)
ncols = 3
nrows = len(p.mu0) // ncols + 1
fig, axes = subplots(nrows, ncols, (DOUBLE, 2.3 * nrows), (0.5, 0.1, 0.4, 0.22), (0.55, 0.6))
panels, dist_ax = axes.flat[: len(p.mu0)], axes.flat[len(p.mu0)]
for ax in axes.flat[len(p.mu0) + 1 :]:
    ax.remove()

# %%
for i, (ax, mu0, span) in enumerate(zip(panels, p.mu0, p.t_span, strict=True)):
    t = np.linspace(*span, p.n_points)
    z = turntable.solve(p.state, t, mu0, p.k)
    alpha1 = turntable.spectrum(mu0, p.k).alpha1
    ax.plot(z[:, 0], z[:, 1], color=f"C{i}", lw=0.9)
    ax.plot(*p.state[:2], "o", mfc="w", mec="k", ms=4, label="start")
    ax.plot(*centre, "ko", ms=5, label=r"$(x_0, y_0)$")
    # Equal scales in x and y, but every panel keeps the same size (the limits adapt).
    ax.set(aspect="equal", adjustable="datalim", xlabel="$x/R$", ylabel="$y/R$")
    ax.set_title(rf"$\mu_0 = {mu0:g}$, $t\Omega \leq {span[1]:g}$, $\alpha_1 = {alpha1:.2g}$")
    dist = np.hypot(*(z[:, :2] - centre).T)
    dist_ax.plot(t, dist, color=f"C{i}", label=rf"$\mu_0 = {mu0:g}$")
panels[0].legend(loc="lower right", fontsize=6.5, handletextpad=0.2)
dist_ax.set(yscale="log", xlabel=r"time $t\Omega$", ylabel=r"distance from $(x_0, y_0)$ $/R$")
dist_ax.legend(loc="upper right", fontsize=6.5)
save(fig, snakemake)
