"""Run the notebook driver, input ``driver`` of the job (workflow/scripts/run_notebook.py).

The ``script:`` of every rule that runs a script of scripts/ (workflow/rules/common.smk).
Snakemake reruns a job whose ``script:`` file is newer than its outputs, whatever its content,
so that touching the driver, or a git checkout or stash that rewrites it unchanged, would
rerun every notebook job. This stub does not change; the driver is an input of the job, which
Snakemake compares by its content (a checksum) once it is newer than the outputs: a change
of the driver's content reruns every such job, a touch none.
"""

import runpy

runpy.run_path(snakemake.input.driver, init_globals={"snakemake": snakemake}, run_name="__main__")
