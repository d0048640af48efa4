# The executed notebooks, made only when asked for (make notebooks, CI), never by the default
# build: each job that runs a script of scripts/ has a twin that runs the same script as a
# Jupyter notebook (workflow/scripts/as_notebook.py), with the job's inputs and params, and
# writes results/notebooks/<script>.ipynb. What the script writes in the notebook goes
# under results/notebooks/<script>/ (the paths of the job's outputs), not over the build.
NOTEBOOKS = []

for _job in [r for r in list(workflow.rules) if "script" in r.input.keys()]:
    _wildcards = "".join(f"_{{{w}}}" for w in _job.wildcard_names)
    _stem = f"{Path(_job.input.script).stem}{_wildcards}"
    NOTEBOOKS += dict.fromkeys(
        expand(f"results/notebooks/{_stem}.ipynb", k=list(STUDY_K))
    )

    rule:
        name:
            f"notebook_{_job.name}"
        input:
            **dict(_job.input.items()),
        output:
            notebook=ensure(f"results/notebooks/{_stem}.ipynb", non_empty=True),
        log:
            f"logs/notebooks/{_stem}.log",
        conda:
            "../envs/turntable.yaml"
        params:
            **dict(_job.params.items()),
            outputs=moved_outputs(_job, f"results/notebooks/{_stem}"),
        script:
            "../scripts/as_notebook.py"


rule notebooks:
    input:
        NOTEBOOKS,
