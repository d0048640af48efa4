"""Compile paper/paper.typ into paper/paper.pdf with the typst Python package.

Run by rule ``paper`` (workflow/rules/paper.smk). The working directory is the Typst root, so
the article reads ../results/claims.json and ../figures/* next to its output; when the
workflow runs in another directory the sources are first copied into its paper/ folder.
System fonts are ignored and the creation date is fixed (config ``paper.timestamp``), so two
builds give the same bytes.
"""

import logging
import shutil
from pathlib import Path

import typst

logging.basicConfig(filename=snakemake.log[0], level=logging.INFO, filemode="w")

out = Path(snakemake.output[0])
for source in map(Path, snakemake.input.sources):
    staged = out.parent / source.name
    if not (staged.exists() and staged.samefile(source)):
        shutil.copyfile(source, staged)
        logging.info("staged %s", staged)

try:
    pdf = typst.compile(
        str(out.parent / snakemake.params.main),
        root=str(Path.cwd()),
        format="pdf",
        ignore_system_fonts=True,
        timestamp=int(snakemake.params.timestamp),
    )
except typst.TypstError as err:
    logging.error("%s\n%s\nhints: %s", err.message, err.diagnostic, err.hints)
    raise
out.write_bytes(pdf)
logging.info("wrote %s (%d bytes)", out, len(pdf))
