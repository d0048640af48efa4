# Every script of scripts/ executed as a Jupyter notebook with its outputs, so that a reader
# sees each figure next to the code that drew it: results/notebooks/<script>.ipynb.
# The notebook of a script runs with the parameters, inputs and configuration of the rule
# that runs the script; its outputs and log go to results/notebooks/<script>/, never to
# figures/ or results/ proper. The rule of each script is looked up when the jobs are
# planned (not at parse time), so rule files included after this one are seen too.
include: "notebook_functions.smk"


rule notebooks:
    input:
        NOTEBOOKS,


rule notebook:
    input:
        script="scripts/{name}.py",
        runner="workflow/scripts/run_notebook.py",
        rule_inputs=notebook_inputs,
    output:
        notebook="results/notebooks/{name}.ipynb",
        files=directory("results/notebooks/{name}"),
    log:
        "logs/notebooks/{name}.log",
    wildcard_constraints:
        name="|".join(NOTEBOOK_NAMES),
    conda:
        "../envs/notebooks.yaml"
    params:
        spec=lambda wildcards: notebook_spec(wildcards.name),
    script:
        "../scripts/run_notebook.py"
