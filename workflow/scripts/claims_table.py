"""The claims table with the verdicts as an HTML page of the report (results/claims.html).

Run by rule ``claims_table`` (workflow/rules/report.smk); the layout is
turntable.claims.report.to_html, the same columns as results/claims.md.
"""

import json
import logging
from pathlib import Path

from turntable._atomic import write_text
from turntable.claims.report import to_html

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")
report = json.loads(Path(snakemake.input[0]).read_text(encoding="utf-8"))
out = snakemake.output[0]
write_text(out, to_html(report))
logging.info("wrote %s: %s", out, report["summary"])
