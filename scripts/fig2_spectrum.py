# %%
"""Figure 2: the real parts alpha1, alpha2 and the frequency beta against mu0.

Caption: growth rate alpha1 of the unstable modes, decay rate |alpha2| of the damped modes
and their common frequency beta (2.5), against the friction coefficient mu0 (k = 2/5 by
default), on log-log axes. Dotted: the small-friction asymptote sqrt(mu0/2), shared by all
three rates (drawn where it is within `asymptote_within` of beta); dashed: the
large-friction expansion (3.2); each drawn where its relative difference from the exact
rate is at most `asymptote_within`. The dot marks the maximum of alpha1 (a = golden ratio).
"""

# %%
import numpy as np

import turntable
from _style import SINGLE, save, setup, subplots

setup(snakemake)
k = snakemake.params.k
mu0 = np.geomspace(*snakemake.params.mu0_range, snakemake.params.n_points)
s = turntable.spectrum(mu0, k)
small = turntable.small_friction_expansion(mu0, k)
large = turntable.large_friction_expansion(mu0, k)
peak = turntable.alpha1_peak(k)


def near(approx, exact):
    """The approximation where it is within `asymptote_within` of the exact values, NaN
    elsewhere (relative difference)."""
    close = np.abs(approx / exact - 1.0) <= snakemake.params.asymptote_within
    return np.where(close, approx, np.nan)


# %%
fig, ((ax,),) = subplots(1, 1, (SINGLE, 2.8), margins=(0.55, 0.1, 0.4, 0.22))
for y, label, y_large in [
    (s.alpha1, r"$\alpha_1$", large.alpha1),
    (-s.alpha2, r"$|\alpha_2|$", -large.alpha2),
    (s.beta, r"$\beta$", large.beta),
]:
    ax.plot(mu0, y, label=label, lw=2.0, alpha=0.8)
    ax.plot(mu0, near(y_large, y), "k--", lw=0.7)
ax.plot(
    mu0,
    near(small.beta, s.beta),
    "k:",
    lw=1.0,
    label=r"small $\mu_0$: all three $\approx \sqrt{\mu_0/2}$",
)
ax.plot([], [], "k--", lw=0.7, label=r"large $\mu_0$: series in $1/\mu_0$")
ax.plot(peak.mu0, peak.alpha1, "o", color="C0", ms=4)
ax.annotate(
    rf"max $\alpha_1 = {peak.alpha1:.4f}$" + "\n" + rf"at $\mu_0 = {peak.mu0:.4f}$",
    (peak.mu0, peak.alpha1),
    (3e-4, 2e-4),
    arrowprops={"arrowstyle": "->", "lw": 0.6},
)
ax.set(xscale="log", yscale="log", xlabel=r"friction $\mu_0$ (units of $m\Omega$)")
ax.set(ylabel=r"rate (units of $\Omega$)", title=rf"$k = {k:g}$")
ax.legend(loc="upper left", ncols=1)
save(fig, snakemake)
