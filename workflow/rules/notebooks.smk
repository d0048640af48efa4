# `make notebooks` (target notebooks): every script of scripts/ executed as a Jupyter notebook
# with its outputs, results/notebooks/<script>.ipynb, so that a reader sees each figure next
# to the code that drew it. Each notebook is written by the job that runs its script (see
# notebook() in common.smk and workflow/scripts/run_notebook.py): no script runs twice.


rule notebooks:
    input:
        NOTEBOOKS,
