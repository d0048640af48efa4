# Reproduction of Ivanova (2019), "The Rolling of a Homogeneous Ball with Slipping on a
# Horizontal Rotating Plane". `snakemake --cores all` builds every output.
import sys
from pathlib import Path

from snakemake.exceptions import WorkflowError
from snakemake.utils import min_version

min_version("9.0")

sys.path.insert(0, f"{workflow.basedir}/workflow")
from config_checks import config_problem, file_problem

CONFIGFILE = "config/config.yaml"

# Stop before any job runs if the configuration is malformed, with a message that names
# the file, the line and the key (workflow/config_checks.py): first the YAML syntax, which
# Snakemake would report without a line, then types, bounds, missing or unknown keys, and
# the rules a schema cannot express.
if Path(CONFIGFILE).exists() and (problem := file_problem(CONFIGFILE)):
    raise WorkflowError(problem)


configfile: CONFIGFILE


if problem := config_problem(config, [CONFIGFILE, *workflow.overwrite_configfiles]):
    raise WorkflowError(problem)


include: "workflow/rules/common.smk"
include: "workflow/rules/film.smk"
include: "workflow/rules/figures.smk"
include: "workflow/rules/claims.smk"
include: "workflow/rules/paper.smk"
include: "workflow/rules/study.smk"
include: "workflow/rules/report.smk"
include: "workflow/rules/docs.smk"
include: "workflow/rules/animation.smk"
# last: target `notebooks` lists the notebooks of the rules above
include: "workflow/rules/notebooks.smk"


rule all:
    default_target: True
    input:
        FIGURES,
        FILM_OUTPUTS,
        "figures/animation.gif",
        "results/claims.json",
        "results/claims.md",
        "results/claims.html",
        "results/figures.html",
        "paper/paper.pdf",
        STUDY_OUTPUTS,
        NOTEBOOKS,
