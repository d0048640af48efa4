# %%
"""Synthetic films: the exact motion of each configured ball plus Gaussian tracking noise.

Writes results/film/<name>.csv (t, x, y in s and m) for each film of the configuration
section synthetic_film, on the ball, turntable and camera of section film; the header marks
the file SYNTHETIC and gives the true parameters. The rolling ball starts from the start of
section film projected on the no-slip constraint (turntable.no_slip_state). The truth of
every film also goes to results/film/synthetic.json (marked synthetic), which the report
page and the article read beside the fits.
"""

# %%
import json
import logging
from pathlib import Path

import turntable as tt
from turntable import film, fit
from turntable._atomic import write_text

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")
p = snakemake.params
rig = film.rig_from_config(p.film)
truth = {
    "synthetic": True,
    "note": "SYNTHETIC DATA: simulated by turntable.fit.simulate_film, not measured",
    "setup": {
        "radius_m": rig.setup.radius,
        "omega_rad_s": rig.setup.omega,
        "k": rig.setup.k,
        "axis_m": list(rig.setup.axis),
    },
    "camera": {
        "fps": rig.camera.fps,
        "noise_m": rig.camera.noise,
        "duration_s": rig.camera.duration,
    },
    "films": {},
}

# %%
for path in snakemake.output.csv:
    name = Path(path).stem
    spec = p.films[name]
    z0 = rig.state0
    if spec["model"] == "rolling_resistance":
        z0 = tt.no_slip_state(z0, rig.setup.k)
    args = (spec["model"], spec["coefficient"], z0, rig.setup, rig.camera, spec["seed"])
    data = fit.simulate_film(*args)
    film.write_film(path, data, fit.synthetic_header(*args))
    truth["films"][name] = {
        "csv": path,
        "model": spec["model"],
        "coefficient": spec["coefficient"],
        "seed": spec["seed"],
        "state0": [float(v) for v in z0],
        "n_frames": int(data.t.size),
    }
    logging.info("wrote %s: %d frames of %s", path, data.t.size, spec)

# %%
write_text(snakemake.output.truth, json.dumps(truth, indent=1))
