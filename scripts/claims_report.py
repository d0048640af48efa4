"""Evaluate the claims registry and write results/claims.json and results/claims.md.

Run by rule ``claims`` (workflow/rules/claims.smk); the parameters are the ``claims:`` section
of config/config.yaml.
"""

import logging
from pathlib import Path

from turntable.claims.report import git_commit, write_reports

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")

report = write_reports(
    snakemake.output.json,
    snakemake.output.md,
    dict(snakemake.params.claims),
    commit=git_commit(Path(snakemake.scriptdir).parent),
)
logging.info("claims: %s", report["summary"])
for cid in report["order"]:
    logging.info("%-32s %s", cid, report["claims"][cid]["verdict"])
