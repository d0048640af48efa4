"""Run one script of scripts/ as a Jupyter notebook: the job's one execution of the script.

Run by workflow/scripts/notebook_job.py, the ``script:`` of every rule that runs a script of
scripts/ (see workflow/rules/common.smk), of which this driver is input ``driver``.
The script (input ``script``) is read with jupytext, its ``# %%`` cells becoming notebook
cells and its docstring a Markdown cell. A first code cell defines the job's ``snakemake``
object from plain values (its inputs but the code, its outputs but the notebook, log,
parameters, wildcards, and the rule's own section of the configuration, if it has one, never
the others: a notebook changes only when its job reruns); a last one shows what the script
wrote. The notebook is executed once, cell by cell, in an IPython shell in this process (as a
Jupyter kernel of this interpreter would run it, without the kernel's process and messages),
and saved with its outputs as output ``notebook``: the outputs of the job are those the
notebook wrote.

The first cell holds a switch: run by this driver (environment variable TURNTABLE_NOTEBOOK
names the notebook), it writes the job's outputs; run by hand, it writes them and the log under
results/notebooks/<name>/ instead. The cell saved is the cell executed. Cell ids are the cell's
index, and no timing is recorded, so that two runs write the same bytes. A failing cell ends
the job with its traceback, without colour codes.

Snakemake's own ``notebook:`` directive is not used: it runs .ipynb files only, not jupytext
scripts, and its first cell holds a pickled object and an absolute path.

Executed in this process rather than by nbclient on a kernel, the notebook has the same bytes
(checked on every script: the same outputs, counts and metadata) at about 0.3 s less CPU per
job (no kernel to start, no jupyter_client, zmq or nbclient to import). What a script writes
to the file descriptors 1 and 2 directly (a subprocess, a C library), which a kernel would
capture, goes to the job's log instead.
"""

import ast
import io
import os
import pprint
import re
import sys
from pathlib import Path

import jupytext
import nbformat
from IPython.core.displaypub import DisplayPublisher
from IPython.core.interactiveshell import InteractiveShell
from traitlets.config import Config

SCRIPT = Path(snakemake.input.script)
NOTEBOOK = Path(snakemake.output.notebook)

# Inputs the script does not read: its own source, this driver and the code the job
# depends on.
NOT_SHOWN_INPUTS = {"script", "driver", "code"}

PREAMBLE = '''\
# The `snakemake` object that rule {rule} gives {script}.
# Run by the workflow, this notebook wrote the job's outputs. Run by hand, it writes
# them, and the log, under OUT = {outdir}/
# instead, so that it never overwrites what the workflow built.
# (Inputs left out: the script, the notebook driver and the code the job depends on.)
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


def own_section(rule: str, config: dict) -> dict:
    """The section of the configuration named after the rule, if any: the notebook holds
    nothing of the other sections, which do not rerun the job when they change (scripts
    read their values from params)."""
    return {rule: config[rule]} if rule in config else {}


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
    config=literal(own_section(snakemake.rule, snakemake.config), len("    config=")),
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

# The cells run here, in this process, in an IPython shell, as a Jupyter kernel runs them
# (the same shell, display formatters and traceback, a cell's last value not echoed), with
# what they display or print captured as the cell's outputs, as a kernel sends them to
# nbclient: no kernel process, no messages (that cost each job a second of CPU).
outputs: list = []  # the outputs of the cell that runs


class Publisher(DisplayPublisher):
    """display(...) of a cell: a display_data output, as ipykernel sends it."""

    def publish(self, data, metadata=None, source=None, *, transient=None, update=False):
        outputs.append(nbformat.v4.new_output("display_data", data=data, metadata=metadata or {}))

    def clear_output(self, wait=False):
        outputs.clear()


class Stream(io.TextIOBase):
    """sys.stdout or sys.stderr of the cells: a stream output (consecutive writes joined).
    Installed once: a script that redirects them (to its log) keeps them redirected."""

    encoding = "utf-8"

    def __init__(self, name: str) -> None:
        self.name = name

    def writable(self) -> bool:
        return True

    def write(self, text: str) -> int:
        last = outputs[-1] if outputs else None
        if last is not None and last.output_type == "stream" and last.name == self.name:
            last.text += text
        else:
            outputs.append(nbformat.v4.new_output("stream", name=self.name, text=text))
        return len(text)


class Shell(InteractiveShell):
    """A failing cell's traceback as an error output, as ipykernel sends it."""

    def _showtraceback(self, etype, evalue, stb):
        outputs.append(
            nbformat.v4.new_output(
                "error", ename=etype.__name__, evalue=str(evalue), traceback=list(stb)
            )
        )


config = Config()
config.HistoryManager.enabled = False  # no history file
config.InteractiveShell.ast_node_interactivity = "none"  # as in a script: repr may hold an address
config.InteractiveShell.colors = "nocolor"
os.environ["TURNTABLE_NOTEBOOK"] = NOTEBOOK.as_posix()  # the first cell: run by the workflow
shell = Shell.instance(config=config, display_pub_class=Publisher)
saved_streams = sys.stdout, sys.stderr
sys.stdout, sys.stderr = Stream("stdout"), Stream("stderr")
try:
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        outputs = cell.outputs = []
        cell.execution_count = shell.execution_count  # 1, 2, ... as a kernel counts
        result = shell.run_cell(cell.source, store_history=True)
        if not result.success:
            break
finally:
    sys.stdout, sys.stderr = saved_streams
errors = [o for o in outputs if o.output_type == "error"]
if errors or not result.success:
    message = "\n".join(errors[-1].traceback) if errors else repr(result.error_in_exec)
    message = re.sub(r"\x1b\[[0-9;]*m", "", message)
    raise SystemExit(
        f"{SCRIPT} failed, run as a notebook (In[1] is the snakemake object):\n{message.strip()}"
    )
# What the kernel reports to nbclient about its language, which nbclient saves.
nb.metadata["language_info"] = {
    "codemirror_mode": {"name": "ipython", "version": sys.version_info[0]},
    "file_extension": ".py",
    "mimetype": "text/x-python",
    "name": "python",
    "nbconvert_exporter": "python",
    "pygments_lexer": f"ipython{sys.version_info[0]}",
    "version": sys.version.split()[0],
}

tmp_notebook = NOTEBOOK.with_name(f".{NOTEBOOK.name}.partial")
nbformat.write(nb, tmp_notebook)
os.replace(tmp_notebook, NOTEBOOK)
