"""Run one script of scripts/ as a Jupyter notebook: the job's one execution of the script.

The ``script:`` of every rule that runs a script of scripts/ (see workflow/rules/common.smk).
The script (input ``script``) is read with jupytext, its ``# %%`` cells becoming notebook
cells and its docstring a Markdown cell. A first code cell defines the job's ``snakemake``
object from plain values (its inputs but the code, its outputs but the notebook, log,
parameters, wildcards and configuration); a last one shows what the script wrote. The
notebook is executed once, with nbclient, on a kernel of this interpreter, and saved with its
outputs as output ``notebook``: the outputs of the job are those the notebook wrote.

The first cell holds a switch: run by this driver (environment variable TURNTABLE_NOTEBOOK
names the notebook), it writes the job's outputs; run by hand, it writes them and the log under
results/notebooks/<name>/ instead. The cell saved is the cell executed. Cell ids are the cell's
index, and no timing is recorded, so that two runs write the same bytes. A failing cell ends
the job with its traceback, without colour codes.

Snakemake's own ``notebook:`` directive is not used: it runs .ipynb files only, not jupytext
scripts, and its first cell holds a pickled object and an absolute path.
"""

import os
import signal
import sys
import tempfile
from pathlib import Path

from jupyter_client.manager import AsyncKernelManager
from jupyter_core.utils import run_sync

SCRIPT = Path(snakemake.input.script)
NOTEBOOK = Path(snakemake.output.notebook)

# The kernel, started first, so that it boots while the notebook is made: this interpreter
# (python3 is the kernel of the first python on PATH), over IPC sockets in a temporary
# folder (TCP would warn that it is not encrypted), no history file, and, as in a script, a
# cell's last value not echoed (its repr may hold a memory address).
os.environ["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"
tmp = tempfile.TemporaryDirectory()
kernel_err = open(Path(tmp.name, "kernel.err"), "w+")  # noqa: SIM115 (closed at the end)
kernel = AsyncKernelManager(
    kernel_name="python3", transport="ipc", ip=str(Path(tmp.name, "kernel"))
)
run_sync(kernel.start_kernel)(
    extra_arguments=[
        "--HistoryManager.enabled=False",
        "--InteractiveShell.ast_node_interactivity=none",
    ],
    env=os.environ
    | {"TURNTABLE_NOTEBOOK": NOTEBOOK.as_posix(), "PYDEVD_DISABLE_FILE_VALIDATION": "1"},
    cwd=os.getcwd(),
    stderr=kernel_err,
)

import ast
import pprint
import re

import jupytext
import nbformat
from nbclient import NotebookClient

# Inputs the script does not read: its own source and the code the job depends on.
NOT_SHOWN_INPUTS = {"script", "code"}

PREAMBLE = '''\
# The `snakemake` object that rule {rule} gives {script}.
# Run by the workflow, this notebook wrote the job's outputs. Run by hand, it writes
# them, and the log, under OUT = {outdir}/
# instead, so that it never overwrites what the workflow built.
# (Inputs left out: the script and the code the job depends on.)
import os
import sys
from pathlib import Path
from types import SimpleNamespace

BY_WORKFLOW = os.environ.get("TURNTABLE_NOTEBOOK") == "{notebook}"
if not BY_WORKFLOW:  # Jupyter starts in the notebook's folder: go up to the project
    while not Path("{notebook}").exists() and Path.cwd() != Path.cwd().parent:
        os.chdir("..")
OUT = "" if BY_WORKFLOW else "{outdir}/"


class Named(list):
    """Like Snakemake's input, output, log and params: a list whose items may have names,
    read as attributes (output.pdf) or keys (output["pdf"])."""

    def __getitem__(self, key):
        return getattr(self, key) if isinstance(key, str) else list(self)[key]


def named(*items, _files=True, **names):
    """A Named list: the unnamed items, then the named ones (a named list of files counts
    as several items, a named parameter as one)."""
    result = Named(items)
    for key, value in names.items():
        setattr(result, key, value)
        result.extend(value if _files and isinstance(value, list) else [value])
    return result


snakemake = SimpleNamespace(
    rule={rule!r},
    input={input},
    output={output},
    log={log},
    params={params},
    wildcards={wildcards},
    threads={threads},
    scriptdir=str(Path({scriptdir!r}).resolve()),
    config={config},
)
sys.path.insert(0, snakemake.scriptdir)  # where the scripts' shared module _style is
for path in [*snakemake.output, *snakemake.log]:
    Path(path).parent.mkdir(parents=True, exist_ok=True)
'''

SHOW = """\
# What the script wrote: figures inline, Markdown rendered, the size of other files; its log.
from IPython.display import Image, Markdown, Pretty, display

for path in map(Path, snakemake.output):
    if path.suffix == ".png":
        display(Image(filename=path, width=700))
    elif path.suffix == ".md":
        display(Markdown(path.read_text()))
    else:
        display(Markdown(f"`{path}`: {path.stat().st_size} bytes"))
for path in map(Path, snakemake.log):
    display(Pretty(f"{path}:\\n{path.read_text()}"))
"""


def literal(value: object, indent: int) -> str:
    """A Python literal of `value`, laid out for reading at the given indentation."""
    text = pprint.pformat(value, width=92 - indent, sort_dicts=False)
    return text.replace("\n", "\n" + " " * indent)


def split(named_list: object, files: bool) -> tuple[list, dict]:
    """The unnamed items and the named ones of a Snakemake input, output, log or params.

    Snakemake, like a Python call, puts the unnamed items first.
    """
    named = {
        key: [str(v) for v in value] if files and isinstance(value, list) else value
        for key, value in named_list.items()
    }
    count = sum(len(v) if files and isinstance(v, list) else 1 for v in named.values())
    unnamed = list(named_list)[: len(named_list) - count]
    return ([str(v) for v in unnamed] if files else unnamed), named


def named_call(
    named_list: object, files: bool = True, leave_out: set = frozenset(), out: bool = False
) -> str:
    """Source of a ``named(...)`` call holding the items of `named_list` as plain values.

    With `out`, every path is written ``OUT + "path"`` (redirected when run by hand).
    """
    unnamed, named = split(named_list, files)

    def show(value: object, indent: int) -> str:
        if out and isinstance(value, list):
            return "[" + ", ".join(show(v, indent) for v in value) + "]"
        if out:
            return f"OUT + {value!r}"
        return literal(value, indent)

    args = [show(v, 8) for v in unnamed]
    args += [f"{k}={show(v, 9 + len(k))}" for k, v in named.items() if k not in leave_out]
    if not args:
        return "named()"
    if not files:
        args.append("_files=False")
    return "named(\n        " + ",\n        ".join(args) + ",\n    )"


def docstring_as_markdown(cell: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """The script's docstring cell as Markdown (instead of a string echoed as output)."""
    body = ast.parse(cell.source).body
    value = body[0].value if len(body) == 1 and isinstance(body[0], ast.Expr) else None
    if isinstance(value, ast.Constant) and isinstance(value.value, str):
        return nbformat.v4.new_markdown_cell(f"`scripts/{SCRIPT.name}`: {value.value}")
    return cell


outdir = f"results/notebooks/{NOTEBOOK.stem}"
preamble = PREAMBLE.format(
    rule=snakemake.rule,
    script=f"scripts/{SCRIPT.name}",
    notebook=NOTEBOOK.as_posix(),
    outdir=outdir,
    input=named_call(snakemake.input, leave_out=NOT_SHOWN_INPUTS),
    output=named_call(snakemake.output, leave_out={"notebook"}, out=True),
    log=named_call(snakemake.log, out=True),
    params=named_call(snakemake.params, files=False),
    wildcards=named_call(snakemake.wildcards, files=False),
    threads=snakemake.threads,
    scriptdir=os.path.relpath(SCRIPT.parent),
    config=literal(dict(snakemake.config), len("    config=")),
)

nb = jupytext.read(SCRIPT, fmt="py:percent")
cells = [docstring_as_markdown(c) if c.cell_type == "code" else c for c in nb.cells[:1]]
nb.cells = [
    nbformat.v4.new_code_cell(preamble),
    *cells,
    *nb.cells[1:],
    nbformat.v4.new_code_cell(SHOW),
]
for index, cell in enumerate(nb.cells):
    cell.id = f"cell-{index}"
    cell.metadata = {}
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}

client = NotebookClient(nb, km=kernel, timeout=1800, record_timing=False)
try:
    client.execute()
except Exception as err:  # the traceback without colour codes, and what the kernel said
    kernel_err.seek(0)
    errors = [o for c in nb.cells for o in c.get("outputs", []) if o.output_type == "error"]
    message = "\n".join(errors[-1].traceback) if errors else str(err)
    message = re.sub(r"\x1b\[[0-9;]*m", "", message)
    raise SystemExit(
        f"{SCRIPT} failed, run as a notebook (In[1] is the snakemake object):\n"
        f"{message.strip()}\n{kernel_err.read()}"
    ) from None
finally:  # the kernel killed at once, not shut down: every cell has finished by then
    if client.kc is not None:
        client.kc.stop_channels()
    run_sync(kernel.signal_kernel)(signal.SIGKILL)
    run_sync(kernel.cleanup_resources)()
    kernel_err.close()
    tmp.cleanup()

tmp_notebook = NOTEBOOK.with_name(f".{NOTEBOOK.name}.partial")
nbformat.write(nb, tmp_notebook)
os.replace(tmp_notebook, NOTEBOOK)
