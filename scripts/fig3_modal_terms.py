# %%
"""Figure 3: the growing and the decaying parts of x(t).

Caption: the coordinate x(t) = x0 + x+(t) + x-(t) of the centre of the ball split as in
(2.7): x+ (modes alpha1 +- i beta, growing) and x- (modes alpha2 +- i beta, decaying), for
each friction coefficient mu0 of the configuration; initial state x = y = 1, v = w = 0,
k = 2/5 by default, over the configured span (t <= 40 by default, more than one period at
each mu0); each panel gives that span in periods 2 pi/beta. Top: x - x0, x+ and x- on a
linear axis, as in the paper's figure. Bottom: |x+| and |x-| on a log axis, where x-, which
starts small, is seen to fall like exp(alpha2 t) while x+ grows like exp(alpha1 t).
"""

# %%
import numpy as np

import turntable
from _style import DOUBLE, save, setup, subplots

setup(snakemake)
p = snakemake.params
t = np.linspace(*p.t_span, p.n_points)
FLOOR = 1e-6  # the bottom of the log axes, in units of R

# %%
size, margins, gaps = (DOUBLE, 4.3), (0.55, 0.1, 0.4, 0.22), (0.2, 0.45)
fig, axes = subplots(2, len(p.mu0), size, margins, gaps, sharey="row")
for top, low, mu0 in zip(axes[0], axes[1], p.mu0, strict=True):
    terms = turntable.modal_terms(p.state, t, mu0, p.k)
    x = turntable.solve(p.state, t, mu0, p.k)[:, 0]
    top.plot(t, x - terms.centre[:, 0], color="0.75", lw=2.5, label=r"$x - x_0$")
    top.plot(t, terms.plus[:, 0], label=r"$x_+$")
    top.plot(t, terms.minus[:, 0], "--", label=r"$x_-$")
    top.axhline(0.0, color="k", lw=0.4)
    top.set(title=rf"$\mu_0 = {mu0:g}$, $k = {p.k:g}$", xlim=p.t_span)
    periods = (p.t_span[1] - p.t_span[0]) * float(turntable.spectrum(mu0, p.k).beta) / (2 * np.pi)
    top.text(0.95, 0.04, f"span: {periods:.2g} periods $2\\pi/\\beta$", transform=top.transAxes,
             ha="right", fontsize=7)  # fmt: skip
    # The same parts on a log axis: |x-| falls like exp(alpha2 t) from its start, |x+| grows
    # like exp(alpha1 t) (the dips are the zeros of the oscillation).
    low.semilogy(t, np.abs(terms.plus[:, 0]), label=r"$|x_+|$")
    low.semilogy(t, np.abs(terms.minus[:, 0]), "--", label=r"$|x_-|$")
    low.set(xlabel=r"time $t\Omega$", xlim=p.t_span, ylim=(FLOOR, 1e2))
axes[0, 0].set_ylabel(r"displacement (units of $R$)")
axes[1, 0].set_ylabel(r"$|x_\pm|$ (units of $R$), log scale")
axes[0, 0].legend(loc="best")
axes[1, 0].legend(loc="lower left")
save(fig, snakemake)
