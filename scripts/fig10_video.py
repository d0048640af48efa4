# %%
"""Figure 10: from a video to the friction.

Caption: a SYNTHETIC video rendered from the exact solution (configuration section
fig10_video), tracked by `turntable track` and fitted from its track by `turntable fit`. Left, its
first frame with what the tracker found: the rim and the mark's circle as the fitted camera
sees them, the image of the axis, and the ball's track. Middle, the distance of the tracked
centre from the true one, in ball radii, against time. Right, the recovered coefficient of
the true model with two standard errors, against the truth.
"""

# %%
import json
from pathlib import Path

import numpy as np
from scipy.interpolate import CubicSpline

from _style import DOUBLE, save, setup, subplots
from turntable import film
from turntable.video import camera
from turntable.video.decode import Video, rgb

setup(snakemake)
p = snakemake.params
cal = json.loads(Path(snakemake.input.calibration).read_text())
res = json.loads(Path(snakemake.input.fit).read_text())
track = film.read_film(snakemake.input.track)
truth = film.read_film(snakemake.input.truth)
with Video(snakemake.input.video) as video:
    first = rgb(next(video.frames())[2])
fig, axes = subplots(
    1,
    3,
    (DOUBLE, 2.6),
    (0.3, 0.35, 0.55, 0.55),
    (0.55, 0.3),
    gridspec_kw={"width_ratios": (1.9, 1.2, 0.7)},
)

# %%
ax = axes[0, 0]
h0 = np.array(cal["homography_plane_to_image"])
h_ball = np.array(cal["homography_ball_plane_to_image"])
s = np.linspace(0, 2 * np.pi, 361)
circle = np.column_stack([np.cos(s), np.sin(s)])
ax.imshow(first)
for radius, style in ((cal["platter_radius_m"], "-"), (cal["mark_radius_m"], "--")):
    uv = camera.apply(h0, radius * circle)
    ax.plot(uv[:, 0], uv[:, 1], ls=style, color="tab:orange", lw=0.8)
sign = -1.0 if cal["y_mirrored"] else 1.0
uv = camera.apply(h_ball, np.column_stack([track.x, sign * track.y]))
ax.plot(uv[:, 0], uv[:, 1], color="tab:green", lw=0.8)
ax.plot(*camera.apply(h0, np.zeros(2)), "+", color="tab:red", ms=9)
ax.set(xticks=[], yticks=[], title="SYNTHETIC video: rim, mark's circle, axis (+), track")

# %%
ax = axes[0, 1]
# the truth at each tracked time (a rolling shutter's row delay moves it off the frame's)
true_x, true_y = (CubicSpline(truth.t - truth.t[0], c)(track.t) for c in (truth.x, truth.y))
error = np.hypot(track.x - true_x, track.y - true_y) / cal["ball_radius_m"]
ax.plot(track.t, error, ".", ms=2, color="0.3")
ax.set(
    xlabel="t (s)",
    ylabel="|tracked - true| / R",
    ylim=(0, None),
    title=f"rms {np.sqrt(np.mean(error**2)):.3f} R",
)

# %%
ax = axes[0, 2]
true_model = p["model"]
name = {"slipping": "mu0", "rolling_resistance": "delta"}[true_model]
value, se = res[true_model][name], res[true_model][f"{name}_stderr"]
true_value = p["coefficient"]
if value is not None:
    ax.errorbar(0, value, yerr=2 * se, fmt="o", capsize=4, color="tab:blue", label="fitted, 2 SE")
ax.axhline(true_value, color="k", lw=0.8, label="truth")
symbol = {"slipping": r"$\mu_0$", "rolling_resistance": r"$\delta$"}[true_model]
ax.set(xticks=[], xlim=(-1, 1), ylabel=symbol, title=f"selected: {res['selected']}")
ax.legend(fontsize=6, loc="upper center", bbox_to_anchor=(0.5, -0.12), frameon=False)
save(fig, snakemake)
