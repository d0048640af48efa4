# %%
"""Evaluate the claims registry and write results/claims.json and results/claims.md.

Run by rule ``claims`` (workflow/rules/claims.smk); the parameters are the ``claims:`` section
of the configuration.
"""

# %%
import logging
from pathlib import Path

from turntable.claims.report import write_reports
from turntable.provenance import provenance

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")

record = provenance(Path(snakemake.scriptdir).parent)
report = write_reports(
    snakemake.output.json,
    snakemake.output.md,
    dict(snakemake.params.claims),
    commit=record["git_commit"],
    provenance=record,
)
logging.info("claims: %s", report["summary"])
for cid in report["order"]:
    logging.info("%-32s %s", cid, report["claims"][cid]["verdict"])
