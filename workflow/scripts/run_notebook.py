"""Execute one script of scripts/ as a Jupyter notebook and save it with its outputs.

Run by rule ``notebook`` (workflow/rules/notebooks.smk). The script is read with jupytext
(its ``# %%`` cells become notebook cells); a first cell defines a ``snakemake`` object
equivalent to the one the script gets from its own rule (same inputs, parameters and
configuration; outputs and log redirected into results/notebooks/<script>/); a last cell
shows the PNG and Markdown files the script wrote. The notebook is executed with nbclient
on the project's Python (the ``python3`` kernel of the running interpreter).
"""

import json
import logging
import os
import pprint
import sys
import time
from pathlib import Path

import jupytext
import nbformat
from nbclient import NotebookClient

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")
spec = snakemake.params.spec
root = Path.cwd()

PREAMBLE = """\
# The `snakemake` object that rule {rule} passes to {script}: same inputs,
# parameters and configuration, but the outputs and the log go to
# {outdir}/, so running this notebook never touches figures/ or results/.
import os
import sys
from pathlib import Path

from snakemake.iocontainers import InputFiles, Log, Namedlist, OutputFiles, Params, Snakemake
from snakemake.iocontainers import Wildcards

while not Path("Snakefile").exists() and Path.cwd() != Path.cwd().parent:
    os.chdir("..")  # run from the project root, wherever the notebook was opened
sys.path.insert(0, "scripts")


def _namedlist(cls, *items, _ranges=(), **named):
    \"\"\"A Snakemake Namedlist: unnamed items, then named ones (names in _ranges: lists).\"\"\"
    namedlist = cls(toclone=items)
    for name, value in named.items():
        start = len(namedlist)
        namedlist.extend(value if name in _ranges else [value])
        namedlist._set_name(name, start, len(namedlist) if name in _ranges else None)
    return namedlist


config = {config}

snakemake = Snakemake(
    input_={input},
    output={output},
    params={params},
    wildcards={wildcards},
    threads=1,
    resources=Namedlist(fromdict={{"_cores": 1, "_nodes": 1}}),
    log={log},
    config=config,
    rulename={rule!r},
    bench_iteration=None,
    scriptdir=str(Path("scripts").resolve()),
)
for _path in [*snakemake.output, *snakemake.log]:
    Path(_path).parent.mkdir(parents=True, exist_ok=True)
"""

SHOW = """\
# The files the script wrote: figures inline, Markdown rendered.
from IPython.display import Image, Markdown, display

for _path in snakemake.output:
    if _path.endswith(".png"):
        display(Image(filename=_path, width=700))
    elif _path.endswith(".md"):
        display(Markdown(Path(_path).read_text()))
"""


def literal(value: object, indent: int) -> str:
    """A Python literal of `value`, laid out for reading at the given indentation."""
    text = pprint.pformat(value, width=92 - indent, sort_dicts=False)
    return text.replace("\n", "\n" + " " * indent)


def namedlist_call(cls: str, entries: list) -> str:
    """Source of a ``_namedlist(...)`` call rebuilding one Namedlist of the rule."""
    unnamed = [value for name, value, _ in entries if name is None]
    named = [(name, value) for name, value, _ in entries if name is not None]
    ranges = [name for name, _, is_range in entries if is_range]
    args = [cls] + [literal(v, 8) for v in unnamed]
    args += [f"{name}={literal(value, 9 + len(name))}" for name, value in named]
    if ranges:
        args.append(f"_ranges={tuple(ranges)!r}")
    return "_namedlist(\n        " + ",\n        ".join(args) + ",\n    )"


nb = jupytext.read(spec["script"], fmt="py:percent")
intro = nbformat.v4.new_markdown_cell(
    f"`{spec['script']}`, run as a notebook with the parameters of rule `{spec['rule']}` "
    f"(see `README.md`). The first cell stands in for the Snakemake workflow; the others "
    f"are the script's own cells; the last one shows what it wrote."
)
preamble = nbformat.v4.new_code_cell(
    PREAMBLE.format(
        rule=spec["rule"],
        script=spec["script"],
        outdir=spec["outdir"],
        input=namedlist_call("InputFiles", spec["input"]),
        output=namedlist_call("OutputFiles", spec["output"]),
        params=namedlist_call("Params", spec["params"]),
        wildcards=namedlist_call("Wildcards", spec["wildcards"]),
        log=namedlist_call("Log", spec["log"]),
        config=literal(dict(snakemake.config), len("config = ")),
    )
)
nb.cells = [intro, preamble, *nb.cells, nbformat.v4.new_code_cell(SHOW)]
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}

Path(snakemake.output.files).mkdir(parents=True, exist_ok=True)
env_path = os.environ.get("PATH", "")
os.environ["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env_path}"
os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")
start = time.perf_counter()
client = NotebookClient(
    nb,
    kernel_name="python3",
    timeout=900,
    record_timing=False,
    resources={"metadata": {"path": str(root)}},
)
client.execute()
images = sum(
    "image/png" in out.get("data", {})
    for cell in nb.cells
    if cell.cell_type == "code"
    for out in cell.outputs
)
tmp = Path(snakemake.output.notebook).with_suffix(".ipynb.partial")
nbformat.write(nb, tmp)
os.replace(tmp, snakemake.output.notebook)
logging.info(
    "executed %s in %.1f s: %d cells, %d images; %s",
    spec["script"],
    time.perf_counter() - start,
    len(nb.cells),
    images,
    json.dumps({"outputs": [value for _, value, _ in spec["output"]]}),
)
