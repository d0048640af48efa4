# %%
"""Animation: the ball on the turntable, slipping (left) and in the no-slip limit (right).

Caption: top view of the plane turning at rate Omega (spokes; red: one marked spoke), the
ball of radius R with a body-fixed pattern turning with its angular velocity (wx, wy) of
the exact solution and the constant vertical spin wz, the trail of its centre, and the
spiral centre (x0, y0) of (2.8) (cross). Left: viscous slipping for the configured mu0
(turntable.solve). Right: the no-slip limit mu0 -> infinity (turntable.nonholonomic, from
the state after the initial layer), which circles (x0, y0) at the rate k/(k+1) Omega.
"""

# %%
import numpy as np

import turntable
from _style import setup
from _style.animation import Panel, save_gif, side_by_side
from turntable.orientation import ball_angular_velocity, integrate_orientation

setup(snakemake)
p = snakemake.params
t = np.linspace(0.0, p.t_end, (p.n_frames - 1) * p.substeps + 1)
models = {
    f"slipping, μ₀ = {p.mu0:g}": turntable.solve(p.state, t, p.mu0, p.k),
    "no slip (μ₀ → ∞)": turntable.nonholonomic(p.state, t, p.k),
}
attitudes = {
    name: integrate_orientation(t, ball_angular_velocity(z, p.wz)) for name, z in models.items()
}
centre = turntable.spiral_centre(p.state, p.k)
extent = 1.5 + max(np.max(np.hypot(z[:, 0], z[:, 1])) for z in models.values())
panels = {name: Panel(p.size, extent, name) for name in models}

# %%
frames = []
for i in range(0, t.size, p.substeps):
    views = [
        panels[name].draw(t[i], z[: i + 1, :2], z[i, :2], attitudes[name][i], centre)
        for name, z in models.items()
    ]
    frames.append(side_by_side(views))
save_gif(frames, snakemake.output.gif, p.frame_ms)
print(f"wrote {snakemake.output.gif}: {len(frames)} frames, extent {extent:.2f} R")
