# Functions of workflow/rules/notebooks.smk: which rule runs each script, and the
# `snakemake` object its notebook needs (inputs, outputs, log, params, wildcards).
from snakemake.io import apply_wildcards

NOTEBOOK_NAMES = sorted(p.stem for p in Path(workflow.basedir, "scripts").glob("*.py"))
NOTEBOOKS = expand("results/notebooks/{name}.ipynb", name=NOTEBOOK_NAMES)

# The notebook of a script whose rule has wildcards runs one job of that rule; these are
# the wildcard values it uses, per rule name.
NOTEBOOK_WILDCARDS = {
    "study_k": lambda: {"k": str(config["study"]["k"][0])},
}


def script_rule(name):
    """The rule running scripts/<name>.py (its ``script`` directive)."""
    found = [
        r
        for r in workflow.rules
        if r.script is not None
        and Path(r.script).stem == name
        and Path(r.script).parent.name == "scripts"
        and not r.name.startswith("notebook")
    ]
    if len(found) != 1:
        raise WorkflowError(
            f"scripts/{name}.py is run by {len(found)} rules, need exactly one to make "
            f"results/notebooks/{name}.ipynb"
        )
    return found[0]


def _concrete(value, wildcards, what):
    """A rule's input/output/log/param value with the wildcards filled in.

    Paths are made relative to the working directory, as the workflow runs from there.
    """
    if callable(value):
        raise WorkflowError(
            f"notebooks: {what} is a function, which the notebook cannot show"
        )
    if isinstance(value, str):
        path = apply_wildcards(value, wildcards) if wildcards else str(value)
        if Path(path).is_absolute() and Path(path).is_relative_to(Path.cwd()):
            path = str(Path(path).relative_to(Path.cwd()))
        return path
    return value


def _namedlist_spec(items, wildcards, what, redirect=None):
    """A Namedlist of a rule as plain values, [[name or None, value, is_range], ...].

    Unnamed items come one by one; a named item is one value, or for a name that covers
    several items (``sources=[...]``) the list of them, with is_range true.
    """
    values = [_concrete(v, wildcards, what) for v in items]
    if redirect is not None:
        values = [redirect(v) for v in values]
    owner = {}
    for name, (start, end) in items._get_names():
        if end is None:
            owner[start] = (name, start + 1, False)
        else:
            owner[start] = (name, end, True)
    entries, i = [], 0
    while i < len(values):
        if i in owner:
            name, end, is_range = owner[i]
            entries.append([name, values[i:end] if is_range else values[i], is_range])
            i = end
        else:
            entries.append([None, values[i], False])
            i += 1
    return entries


def notebook_spec(name):
    """What the first cell of the notebook of scripts/<name>.py needs, but the configuration.

    The configuration is not a parameter of the notebook rule (the runner reads it), so
    editing one figure's parameters reruns only the notebooks whose rule reads them.
    """
    r = script_rule(name)
    wildcards = NOTEBOOK_WILDCARDS.get(r.name, dict)()
    if set(wildcards) != set(r.wildcard_names):
        raise WorkflowError(
            f"notebooks: rule {r.name} has wildcards {sorted(r.wildcard_names)}; "
            f"set their values in NOTEBOOK_WILDCARDS (workflow/rules/notebooks.smk)"
        )
    outdir = f"results/notebooks/{name}"

    def redirect(path):
        return f"{outdir}/{path}"

    return {
        "script": f"scripts/{name}.py",
        "rule": r.name,
        "outdir": outdir,
        "wildcards": [[key, value, False] for key, value in wildcards.items()],
        "input": _namedlist_spec(r.input, wildcards, f"rule {r.name} input"),
        "output": _namedlist_spec(
            r.output, wildcards, f"rule {r.name} output", redirect
        ),
        "log": _namedlist_spec(r.log, wildcards, f"rule {r.name} log", redirect),
        "params": _namedlist_spec(r.params, wildcards, f"rule {r.name} params"),
    }


def notebook_inputs(wildcards):
    """The inputs of the rule that runs scripts/<name>.py."""
    files = []
    for _name, value, is_range in notebook_spec(wildcards.name)["input"]:
        files.extend(value if is_range else [value])
    return files
