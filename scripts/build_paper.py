# %%
"""Compile paper/paper.typ into paper/paper.pdf with the typst Python package.

Run by rule ``paper`` (workflow/rules/paper.smk). The sources, results/claims.json and the
figures the article shows (the rule's inputs, nothing else) are copied into a temporary
tree with the layout the article expects (paper/, results/, figures/), which
is the Typst root; so the build does not depend on the working directory. System fonts are
ignored and the creation date is fixed (config ``paper.timestamp``), so two builds give the
same bytes. ``results/build.json`` in that tree is the provenance of this build
(turntable.provenance: the commit that builds the PDF, a dirty tree, versions) and the
repository address, read by paper/provenance.typ and attached to the PDF.
"""

# %%
import json
import logging
import shutil
import tempfile
from pathlib import Path

import typst

from turntable.provenance import provenance

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")

with tempfile.TemporaryDirectory() as tmp:
    root = Path(tmp)
    layout = {
        "paper": snakemake.input.sources,
        "results": [snakemake.input.claims],
        "figures": snakemake.input.figures,
    }
    for folder, files in layout.items():
        (root / folder).mkdir(parents=True, exist_ok=True)
        for f in map(Path, files):
            shutil.copyfile(f, root / folder / f.name)
    build = {
        "provenance": provenance(Path(snakemake.scriptdir).parent),
        "repository": snakemake.params.repository.rstrip("/"),
        # values of the configuration other than the defaults (common.smk)
        "config_overrides": list(snakemake.params.config_overrides),
    }
    (root / "results" / "build.json").write_text(json.dumps(build, indent=1, sort_keys=True))
    logging.info("provenance: %s", build)
    try:
        pdf = typst.compile(
            str(root / "paper" / snakemake.params.main),
            root=str(root),
            format="pdf",
            ignore_system_fonts=True,
            timestamp=int(snakemake.params.timestamp),
        )
    except typst.TypstError as err:
        logging.error("%s\n%s\nhints: %s", err.message, err.diagnostic, err.hints)
        raise

out = Path(snakemake.output[0])
out.write_bytes(pdf)
logging.info("wrote %s (%d bytes)", out, len(pdf))
