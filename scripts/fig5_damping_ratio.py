# %%
"""Figure 5: damping of the decaying modes over one period, against mu0.

Caption: (a) N = exp(2 pi |alpha2| / beta), the factor by which the decaying part z- of
the solution shrinks over one period 2 pi / beta (2.9), on a logarithmic axis for several
inertia ratios k, near the lower bound N = e^(2 pi) of (2.10) (black line; below it, grey,
the values (2.10) excludes): every curve starts just above the bound at the smallest mu0 and
leaves the axis upwards. (b) The excess over the bound, ln N / (2 pi) - 1 = |alpha2|/beta - 1
(as in the study figure), on log axes over the whole range: it vanishes only as mu0 -> 0.
"""

# %%
import numpy as np

import turntable
from _style import DOUBLE, save, setup, subplots

setup(snakemake)
p = snakemake.params
mu0 = np.geomspace(*p.mu0_range, p.n_points)
bound = np.exp(2.0 * np.pi)  # the infimum of N in (2.10)
TOP = 1.0e4  # the largest N drawn in (a), near the bound (N grows without bound; (b) goes on)

# %%
fig, ((ax, ax_ex),) = subplots(1, 2, (DOUBLE, 2.6), (0.55, 0.1, 0.4, 0.22), (0.75, 0.0))
for k in p.k:
    log_n = turntable.log_damping_ratio(mu0, k)
    ax.plot(mu0, np.exp(np.minimum(log_n, np.log(10.0 * TOP))), label=f"$k = {k:.3g}$")
    ax_ex.plot(mu0, log_n / (2.0 * np.pi) - 1.0, label=f"$k = {k:.3g}$")
ax.axhspan(0.0, bound, color="0.88", lw=0)
ax.axhline(bound, color="k", lw=1.0)
ax.text(mu0[-1], bound * 0.85, rf"bound $N = e^{{2\pi}} \approx {bound:.1f}$", ha="right",
        va="top", fontsize=7)  # fmt: skip
ax.set(xscale="log", yscale="log", ylabel=r"damping per period $N$", title="(a) damping per period")
ax.set_ylim(bound / 1.6, TOP)
ax_ex.set(xscale="log", yscale="log", ylabel=r"$\ln N / (2\pi) - 1 = |\alpha_2|/\beta - 1$")
ax_ex.set_title("(b) excess over the bound")
for a in (ax, ax_ex):
    a.set_xlabel(r"friction $\mu_0$ (units of $m\Omega$)")
ax.legend(loc="upper left")
save(fig, snakemake)
