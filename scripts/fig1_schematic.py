# %%
"""Figure 1: the model.

Caption: a ball (centre C at r) on a horizontal plane turning at the rate Omega about the
vertical axis Oz (unit vector gamma) of the fixed frame Oxyz. At the contact point P the
ball slips with velocity u relative to the plane; the viscous friction there is -mu0 u.
"""

# %%
import matplotlib.pyplot as plt
import numpy as np

from _style import SINGLE, save, setup, subplots

setup(snakemake)
tilt, lift = snakemake.params.tilt, np.sqrt(1.0 - snakemake.params.tilt**2)


def at(x, y, z=0.0):
    """Screen position of the point (x, y, z) in an oblique view (plane squashed by tilt)."""
    c, s = np.cos(-2.1), np.sin(-2.1)
    return np.array([c * x - s * y, tilt * (s * x + c * y) + lift * z])


def label(ax, point, offset, text, zorder=2):
    """Write `text` centred at `point` shifted by `offset` (screen units)."""
    ax.text(*np.add(point, offset), text, ha="center", va="center", zorder=zorder)


def arrow(ax, a, b, text="", offset=(0.0, 0.0), zorder=2, **kw):
    """Draw an arrow from a to b and write `text` near its tip."""
    style = {"arrowstyle": "-|>", "mutation_scale": 8, "lw": 1.0, "color": "k"} | kw
    ax.annotate("", b, a, arrowprops=style, zorder=zorder, annotation_clip=False)
    label(ax, b, offset, text, zorder)


# %% the plane, the fixed axes and the rotation of the plane
fig, ((ax,),) = subplots(1, 1, (SINGLE, 2.2), margins=(0.0, 0.0, 0.0, 0.0))
phi = np.linspace(0.0, 2.0 * np.pi, 200)
ax.fill(*at(3.3 * np.cos(phi), 3.3 * np.sin(phi)), color="0.9", ec="0.5", lw=0.6)
origin = at(0, 0)
arrow(ax, origin, at(2.6, 0), "$x$", (-0.2, 0.17))  # inside the plane, off its rim
arrow(ax, origin, at(0, 2.8), "$y$", (0.2, 0.05))
arrow(ax, origin, at(0, 0, 2.6), "$z$", (0.0, 0.18))
label(ax, origin, (-0.05, -0.3), "$O$")
ax.plot(*(arc := at(0.35 * np.cos(phi[20:170]), 0.35 * np.sin(phi[20:170]), 2.0)), "k", lw=0.8)
arrow(ax, arc[:, -2], arc[:, -1])
label(ax, at(0, 0, 2.0), (-0.65, 0.05), r"$\Omega$")
# %% the ball, its contact point and the slip velocity
x, y = -2.0, 0.7
ax.plot(*np.c_[origin, at(x, y)], "k:", lw=0.6)
ax.add_patch(plt.Circle(at(x, y, 1.0), 1.0, fc="#9ecae1", ec="#08519c", lw=0.8, zorder=3))
arrow(ax, origin, at(x, y, 1.0), "$C$", (0.3, -0.08), 4, lw=0.8)
label(ax, at(x / 2, y / 2, 0.5), (-0.25, 0.1), r"$\mathbf{r}$", 5)
arrow(ax, at(x, y, 1.0), at(x, y, 2.5), r"$\boldsymbol{\gamma}$", (0.35, -0.25), 4, lw=1.8)
ax.plot(*at(x, y), "ko", ms=3, zorder=5)
label(ax, at(x, y), (-0.1, -0.2), "$P$", 5)
arrow(ax, at(x, y), at(x + 0.8, y + 1.5), r"$\mathbf{u}$", (0.2, 0.0), 5, color="#b2182b", lw=1.3)
ax.set(xlim=(-3.4, 3.4), ylim=(-3.4 * tilt, 2.8 * lift + 0.2), aspect="equal")
ax.axis("off")
save(fig, snakemake)
