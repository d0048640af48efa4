"""Run a job's script (input ``script``, a jupytext percent file) as a Jupyter notebook with
nbclient, and save it with its outputs (output ``notebook``): the record of a run.

A first cell defines the job's ``snakemake`` object from plain values, its outputs (params
``outputs``) under results/notebooks/<name>/; a last one shows what the script wrote. Cell
ids, kernel flags and no timings make two runs write the same bytes.
"""

import os
import pprint
import shutil
from fractions import Fraction
from pathlib import Path

import jupytext
import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError

LEFT_OUT = {"script", "code", "notebook", "outputs"}  # not read by the script


def plain(items, files=True):
    """`Namedlist(...)` source of a Snakemake input, output, log, params or wildcards."""
    if files and not list(items.keys()):
        return f"Namedlist(toclone={[str(v) for v in items]!r})"
    named = {
        k: [str(f) for f in v] if files and isinstance(v, list) else v
        for k, v in items.items()
        if k not in LEFT_OUT
    }
    return fromdict(named)


class Printer(pprint.PrettyPrinter):
    """pprint, with a float that is a fraction of small integers written as one: ``100 / 3``
    for 33.333333333333336, the same number."""

    def format(self, obj, context, maxlevels, level):
        if type(obj) is float and len(repr(obj)) > 12:
            fraction = Fraction(obj).limit_denominator(1000)
            if fraction.numerator / fraction.denominator == obj:
                return f"{fraction.numerator} / {fraction.denominator}", True, False
        return super().format(obj, context, maxlevels, level)


def fromdict(named):
    """`Namedlist(fromdict=...)` source of a dict."""
    text = Printer(width=70, sort_dicts=False).pformat(named).replace("\n", "\n" + " " * 17)
    return f"Namedlist(\n        fromdict={text},\n    )"


FOLDER = os.path.splitext(snakemake.output.notebook)[0]
outputs = snakemake.params.outputs
shutil.rmtree(FOLDER, ignore_errors=True)
for value in outputs.values():
    for path in value if isinstance(value, list) else [value]:
        Path(path).parent.mkdir(parents=True, exist_ok=True)
RULE = snakemake.rule.removeprefix("notebook_")
FIRST = f"""\
# The `snakemake` object of rule {RULE}: run from the repository's root, its outputs moved
# under {FOLDER}/.
import sys
from types import SimpleNamespace

from snakemake.iocontainers import Namedlist

snakemake = SimpleNamespace(
    rule={RULE!r},
    input={plain(snakemake.input)},
    output={fromdict(outputs)},
    log={plain(snakemake.log)},
    params={plain(snakemake.params, files=False)},
    wildcards={plain(snakemake.wildcards, files=False)},
    scriptdir={os.path.relpath(os.path.dirname(snakemake.input.script))!r},
)
sys.path.insert(0, snakemake.scriptdir)  # where the module _style is
"""
LAST = """\
# What the script wrote: figures inline, the size of the other files.
from pathlib import Path

from IPython.display import Image, Markdown, display

for item in snakemake.output:
    for path in map(Path, item if isinstance(item, list) else [item]):
        if path.suffix == ".png":
            display(Image(filename=path, width=700))
        else:
            display(Markdown(f"`{path}`: {path.stat().st_size} bytes"))
"""

nb = jupytext.read(snakemake.input.script, fmt="py:percent")
nb.cells = [nbformat.v4.new_code_cell(FIRST), *nb.cells, nbformat.v4.new_code_cell(LAST)]
for index, cell in enumerate(nb.cells):
    cell.id, cell.metadata = f"cell-{index}", {}
os.environ["MPLBACKEND"] = "Agg"
client = NotebookClient(
    nb,
    kernel_name="python3",
    resources={"metadata": {"path": "."}},
    record_timing=False,
    extra_arguments=[
        "--InteractiveShell.ast_node_interactivity=none",
        "--colors=nocolor",
        "--HistoryManager.enabled=False",
        "--IPKernelApp.log_level=ERROR",  # not its warning of TCP on localhost, every job
    ],
)
try:
    client.execute()
except CellExecutionError as exc:
    raise SystemExit(f"{snakemake.input.script} failed as a notebook:\n{exc}") from None
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbformat.write(nb, snakemake.output.notebook)
