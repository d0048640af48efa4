# %%
"""Synthetic films: the exact motion of each configured ball plus Gaussian tracking noise.

Writes results/film/<name>.csv (t, x, y in s and m) for each film of the configuration
section synthetic_film, on the ball, turntable and camera of section film; the header marks
the file SYNTHETIC and gives the true parameters. The rolling ball starts from the start of
section film projected on the no-slip constraint (turntable.no_slip_state).
"""

# %%
import logging
from pathlib import Path

import turntable as tt
from turntable import film

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")
p = snakemake.params
rig = film.rig_from_config(p.film)

# %%
for path in snakemake.output.csv:
    spec = p.films[Path(path).stem]
    z0 = rig.state0
    if spec["model"] == "rolling_resistance":
        z0 = tt.no_slip_state(z0, rig.setup.k)
    args = (spec["model"], spec["coefficient"], z0, rig.setup, rig.camera, spec["seed"])
    data = film.simulate_film(*args)
    film.write_film(path, data, film.synthetic_header(*args))
    logging.info("wrote %s: %d frames of %s", path, data.t.size, spec)
