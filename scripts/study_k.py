# %%
"""Parameter study, one inertia ratio k: the claims of Section 2 on a grid of mu0.

Writes results/study/k_<k>.json: alpha1, alpha2, beta, ln N, abs(alpha2)/beta and the log
growth per turn at each mu0, the residuals of the root, centre and conservation checks,
and the verdict of each check (turntable.study.section2_checks).
"""

# %%
import json
import logging

import numpy as np

from turntable._atomic import write_text
from turntable.study import section2_checks

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")
p = snakemake.params
k = p.k
mu0 = np.geomspace(*p.mu0_range, p.n_points)
t = np.linspace(*p.t_span, p.n_times)

# %%
result = section2_checks(k, mu0, p.state, t)
for name, ok in result["checks"].items():
    logging.info("k = %g: %-20s %s", k, name, "holds" if ok else "FAILS")

# %%
write_text(snakemake.output[0], json.dumps(result, indent=1) + "\n")
