#!/usr/bin/env bash
# Install the package turntable (src/turntable) into the new environment. Snakemake runs
# this from its working directory, which must be the project root.
set -euo pipefail
python -m pip install --no-deps --quiet "$PWD"
