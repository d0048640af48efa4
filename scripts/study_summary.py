# %%
"""Parameter study, all inertia ratios: summary and figure.

Caption: (a) growth rate alpha1 against mu0 for each k of the study, with the closed-form
maximum (dot). (b) The excess ln N / (2 pi) - 1 = abs(alpha2)/beta - 1 against mu0 on log
axes: positive everywhere (2.10), vanishing only as mu0 -> 0.
Also writes results/study/summary.json (turntable.study.summarize, with its provenance).
"""

# %%
import json
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from _style import DOUBLE, save, setup
from turntable._atomic import write_text
from turntable.provenance import provenance
from turntable.study import summarize

setup(snakemake)
results = [json.loads(Path(path).read_text()) for path in snakemake.input.results]
summary = summarize(results) | {"provenance": provenance(Path(snakemake.scriptdir).parent)}
write_text(snakemake.output.json, json.dumps(summary, indent=1) + "\n")
print("all checks hold" if summary["all_passed"] else f"failed: {summary['failed']}")

# %%
fig, (ax_a, ax_n) = plt.subplots(1, 2, figsize=(DOUBLE, 2.6), layout="constrained")
for i, r in enumerate(results):
    label = rf"$k = {r['k']:.3g}$"
    ax_a.loglog(r["mu0"], r["alpha1"], color=f"C{i}", label=label)
    ax_a.plot(r["peak"]["mu0"], r["peak"]["alpha1"], "o", color=f"C{i}", ms=4)
    ax_n.loglog(r["mu0"], np.asarray(r["decay_ratio"]) - 1.0, color=f"C{i}", label=label)
ax_a.set(xlabel=r"$\mu_0$", ylabel=r"$\alpha_1$", title=r"(a) growth rate $\alpha_1$")
ax_n.set(xlabel=r"$\mu_0$", ylabel=r"$\ln N / (2\pi) - 1 = |\alpha_2|/\beta - 1$")
ax_n.set_title(r"(b) damping per period, excess over the bound $e^{2\pi}$")
ax_a.legend(fontsize=6)
ax_n.legend(fontsize=6)
save(fig, snakemake)
