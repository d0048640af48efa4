# %%
"""The campaign: one row per film of the table, and the coefficient of every film.

Writes results/campaign/summary.csv (turntable.campaign.SUMMARY_COLUMNS, then the table's
labels): the selected model's coefficient with its standard error, whether the selection
is decisive, the warnings; a film turntable fit refused, or a bad row of the table, has the
status failed and the reason. The figure shows mu0 (films that slip) and delta (films that
roll) with two standard errors, grouped by the label group_by (none if empty); hollow
markers: no decisive selection; a cross: the true value of a SYNTHETIC film.
"""

# %%
import json
from pathlib import Path

import matplotlib.pyplot as plt
from matplotlib.ticker import FormatStrFormatter, LogLocator, NullFormatter

from _style import DOUBLE, save, setup
from turntable.campaign import summary_row, write_summary

setup(snakemake)
p = snakemake.params
rows = [
    summary_row(p.films[name], result)
    for path in snakemake.input.fits  # a batch of films each
    for name, result in json.loads(Path(path).read_text()).items()
]
rows += [{"row": b["row"], "file": b["file"], "status": "failed", "warnings": b["error"]}
         for b in p.bad_rows]  # fmt: skip
rows.sort(key=lambda r: r["row"])
write_summary(snakemake.output.csv, rows)
failed = [r for r in rows if r["status"] == "failed"]
print(f"{len(rows) - len(failed)} films fitted, {len(failed)} failed")
for r in failed:
    print(f"{p.table}, row {r['row']} ({r['file']}): {r['warnings']}")

# %%
fitted = [r for r in rows if r["status"] == "fitted"]
groups = sorted({r.get(p.group_by, "") for r in fitted})
fig, axes = plt.subplots(1, 2, figsize=(DOUBLE, 0.6 + 0.3 * max(len(fitted), 4)),
                         layout="constrained", sharey=True)  # fmt: skip
names = {"mu0": r"$\mu_0$ (slipping)", "delta": r"$\delta$ (rolling with resistance)"}
ticks = []
for y, r in enumerate(sorted(fitted, key=lambda r: (r.get(p.group_by, ""), r["film"]))):
    ax = axes[int(r["coefficient"] == "delta")]
    colour = f"C{groups.index(r.get(p.group_by, ''))}"
    face = colour if r["decisive"] else "white"
    ax.errorbar(r["value"], y, xerr=2 * r["stderr"], fmt="o", color=colour, mfc=face)
    if r.get("true_value"):  # a SYNTHETIC film's true value
        ax.plot(float(r["true_value"]), y, "k+", ms=9, zorder=3)
    ticks.append(r["film"])
for ax, name in zip(axes, names.values(), strict=True):
    ax.set(xscale="log", xlabel=name)
    ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
    ax.xaxis.set_major_formatter(FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.margins(x=0.15, y=0.1)
    ax.grid(axis="x", alpha=0.3)
axes[0].set_yticks(range(len(ticks)), ticks, fontsize=6)
for i, group in enumerate(groups if p.group_by else []):
    axes[1].plot([], [], "o", color=f"C{i}", label=f"{p.group_by} = {group}")
if not all(r["decisive"] for r in fitted):
    axes[1].plot([], [], "o", color="grey", mfc="white", label="selection not decisive")
if any(r.get("true_value") for r in fitted):
    axes[1].plot([], [], "k+", ms=9, label="true value (SYNTHETIC)")
axes[1].legend(fontsize=6, loc="best")
if failed:
    fig.suptitle(f"{len(failed)} of {len(rows)} films failed: see summary.csv", fontsize=7)
save(fig, snakemake)
