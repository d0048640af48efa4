"""The claims table with the verdicts as an HTML page of the report (results/claims.html).

Run by rule ``claims_table`` (workflow/rules/report.smk); the layout is
turntable.claims.report.to_html, the same columns as results/claims.md.
"""

import json
import logging
import os
from pathlib import Path

from turntable.claims.report import to_html

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")
report = json.loads(Path(snakemake.input[0]).read_text(encoding="utf-8"))
out = Path(snakemake.output[0])
tmp = out.with_name(f".{out.name}.partial")
tmp.write_text(to_html(report), encoding="utf-8")
os.replace(tmp, out)
logging.info("wrote %s: %s", out, report["summary"])
