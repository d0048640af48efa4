# The HTML report (`make report`, i.e. `snakemake --report results/report.html`): one
# self-contained page with every figure registered with report(...) in the rules, under its
# category, with the caption from workflow/report/<figure>.rst. This file only sets the
# page's introduction.


report: "../report/workflow.rst"
