"""Render the SYNTHETIC video of Fig. 10 and write the true positions of its frames."""

import logging

import turntable as tt
from turntable import film
from turntable.video.render import Scene, render_video

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")
p = snakemake.params
rig = film.rig_from_config(p.film)
setup = rig.setup._replace(axis=(0.0, 0.0))
v = p.video
z0 = rig.state0
if v["model"] == "rolling_resistance":
    z0 = tt.no_slip_state(z0, setup.k)
scene = Scene(
    platter_radius=v["platter_radius_m"],
    tilt_deg=v["tilt_deg"],
    roll_deg=v["roll_deg"],
    size=tuple(v["size"]),
    fps=v["fps"],
    duration=v["duration_s"],
    noise=v["noise"],
)
rendered = render_video(
    snakemake.output.video, v["model"], v["coefficient"], z0, setup, scene, v["seed"]
)
film.write_film(
    snakemake.output.truth,
    rendered.film,
    [
        "SYNTHETIC DATA: the true positions of the ball of the rendered video, not measured",
        f"truth: model = {v['model']}, coefficient = {v['coefficient']!r}; camera: tilt "
        f"{v['tilt_deg']} deg, roll {v['roll_deg']} deg, focal {rendered.pose.focal:.6g} px",
    ],
)
logging.info("rendered %s: %d frames", snakemake.output.video, rendered.film.t.size)
