"""Compile paper/paper.typ into paper/paper.pdf with the typst Python package.

Run by rule ``paper`` (workflow/rules/paper.smk). The project root is the Typst root, so the
article reads ../results/claims.json and ../figures/*.png; system fonts are ignored and the
creation date is fixed (config ``paper.timestamp``) so that two builds give the same bytes.
"""

import logging
from pathlib import Path

import typst

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")

pdf = typst.compile(
    snakemake.params.main,
    root=str(Path.cwd()),
    format="pdf",
    ignore_system_fonts=True,
    timestamp=int(snakemake.params.timestamp),
)
Path(snakemake.output[0]).write_bytes(pdf)
logging.info("wrote %s (%d bytes)", snakemake.output[0], len(pdf))
