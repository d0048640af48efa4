# %%
"""Figure 9: synthetic films fitted with `turntable fit`.

Caption: one row per synthetic film (configuration section synthetic_film): left, the
tracked positions and the paths of both fitted models (read from the JSON the command
wrote; the model not selected dashed); middle, the residuals per coordinate against time
(points: each frame; line: rms over a moving window), labelled with each fitted
coefficient; right, for every film, the recovered coefficient of the true model minus the
truth in units of its standard error (bars: two standard errors), and the AICc difference
in favour of the selected model (hatched if not decisive). The data are SYNTHETIC
(simulated, marked so in their files and in the JSON).
"""

# %%
import json
from pathlib import Path

from matplotlib.lines import Line2D

from _style import DOUBLE, save, setup, subplots
from turntable import film, fit
from turntable.fit import plot as fitplot

setup(snakemake)
p = snakemake.params
names = list(p.films)
films = [film.read_film(path) for path in snakemake.input.csv]
results = [json.loads(Path(path).read_text()) for path in snakemake.input.json]
fig, axes = subplots(
    len(names),
    3,
    (DOUBLE, 2.5 * len(names) + 1.0),
    (0.6, 0.15, 0.45, 0.6),
    (0.7, 0.85),
    gridspec_kw={"width_ratios": (1.0, 1.45, 0.75)},
)

# %%
for row, name, data, res in zip(axes, names, films, results, strict=True):
    truth = p.films[name]
    fitplot.draw_paths(row[0], data, res)
    fitplot.draw_residuals(row[1], data, res, coefficients=True)
    # a decade and a half of headroom above the residuals for the legend
    low, high = row[1].get_ylim()
    row[1].set_ylim(low, high * 10**1.5)
    row[1].legend(fontsize=6.5, loc="upper right")
    symbol = {"mu0": r"$\mu_0$", "delta": r"$\delta$"}[fitplot.COEFFICIENT[truth["model"]]]
    selected = res["selected"]
    row[0].set_title(
        f"SYNTHETIC film '{name}': true {symbol} = {truth['coefficient']:g}\n"
        + (f"selected: {fitplot.STYLE[selected][1]}" if selected else "no model selected"),
        fontsize=7,
    )
handles = [Line2D([], [], ls="", marker=".", color="0.6")]
handles += [Line2D([], [], color=fitplot.STYLE[model][0]) for model in fit.MODELS]
handles += [
    Line2D([], [], color="0.4", ls=(0, (4, 2))),
    Line2D([], [], ls="", marker="+", color="k"),
]
labels = ["data", *(fitplot.STYLE[model][1] for model in fit.MODELS), "not selected", "axis"]
fig.legend(handles, labels, loc="upper center", ncols=5, fontsize=7, frameon=False)

# %%
ax_z, ax_aic = axes[0, 2], axes[1, 2]
for i, (name, res) in enumerate(zip(names, results, strict=True)):
    truth = p.films[name]
    coefficient = fitplot.COEFFICIENT[truth["model"]]
    entry = res[truth["model"]]
    if entry[coefficient] is not None and entry[f"{coefficient}_stderr"]:
        z = (entry[coefficient] - truth["coefficient"]) / entry[f"{coefficient}_stderr"]
        ax_z.errorbar(i, z, yerr=2.0, fmt="o", color=fitplot.STYLE[truth["model"]][0], capsize=3)
    else:  # a limit, not a value (turntable fit warned)
        ax_z.text(i, 0.0, "limit only", ha="center", fontsize=6)
    sel = res["selection"]
    if res["selected"] is not None and sel["aicc_difference"] is not None:
        ax_aic.bar(
            i,
            sel["aicc_difference"],
            color=fitplot.STYLE[res["selected"]][0],
            hatch=None if sel["decisive"] else "//",
        )
ax_z.axhline(0.0, color="k", lw=0.8)
ax_z.set(ylim=(-4.5, 4.5), ylabel="(fitted - true) / standard error")
ax_aic.axhline(fit.DECISIVE, color="0.5", lw=0.6, ls=":")  # decisive above
ax_aic.set(yscale="log", ylim=(1.0, None), ylabel="AICc difference, selected model")
ax_z.set_title("true coefficient recovered", fontsize=7)
ax_aic.set_title("evidence for the selection", fontsize=7)
for ax in (ax_z, ax_aic):
    ticks = [f"film\n'{name}'" for name in names]
    ax.set(xticks=range(len(names)), xticklabels=ticks, xlim=(-0.7, len(names) - 0.3))
for ax in axes[2:, 2]:
    ax.axis("off")
save(fig, snakemake)
