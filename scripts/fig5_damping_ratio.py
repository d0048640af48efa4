# %%
"""Figure 5: damping of the decaying modes over one period, against mu0.

Caption: (a) log10 N, where N = exp(2 pi |alpha2| / beta) is the factor by which the
decaying part z- of the solution shrinks over one period 2 pi / beta (2.9), for several
inertia ratios k. Dotted: the lower bound log10 e^(2 pi) of (2.10). (b) The excess over the
bound, ln N / (2 pi) - 1 = |alpha2|/beta - 1 (as in the study figure), on log axes: it
vanishes only as mu0 -> 0.
"""

# %%
import numpy as np

import turntable
from _style import DOUBLE, save, setup, subplots

setup(snakemake)
p = snakemake.params
mu0 = np.geomspace(*p.mu0_range, p.n_points)
bound = 2.0 * np.pi / np.log(10.0)  # log10 of e^(2 pi), the infimum of N in (2.10)

# %%
fig, ((ax, ax_ex),) = subplots(1, 2, (DOUBLE, 2.6), (0.55, 0.1, 0.4, 0.22), (0.75, 0.0))
for k in p.k:
    log_n = turntable.log_damping_ratio(mu0, k)
    ax.plot(mu0, log_n / np.log(10.0), label=f"$k = {k:.3g}$")
    ax_ex.plot(mu0, log_n / (2.0 * np.pi) - 1.0, label=f"$k = {k:.3g}$")
ax.axhline(bound, color="k", ls=":", lw=1.0, label=rf"$2\pi \log_{{10}} e = {bound:.4f}$")
ax.set(xscale="log", yscale="log", ylabel=r"$\log_{10} N$", title="(a) damping per period")
ax_ex.set(xscale="log", yscale="log", ylabel=r"$\ln N / (2\pi) - 1 = |\alpha_2|/\beta - 1$")
ax_ex.set_title("(b) excess over the bound")
for a in (ax, ax_ex):
    a.set_xlabel(r"friction $\mu_0$ (units of $m\Omega$)")
ax.legend(loc="upper left")
save(fig, snakemake)
