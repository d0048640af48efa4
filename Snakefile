# Reproduction of Ivanova (2019), "The Rolling of a Homogeneous Ball with Slipping on a
# Horizontal Rotating Plane". `snakemake --cores all` builds every output.
from snakemake.utils import min_version, validate

min_version("9.0")


configfile: "config/config.yaml"


# Stop before any job runs if the configuration is malformed: first the JSON schema
# (types, bounds, missing or unknown keys), then the checks the schema cannot express.
validate(config, "workflow/schemas/config.schema.yaml", set_default=False)


include: "workflow/rules/common.smk"


check_config(config)


include: "workflow/rules/figures.smk"
include: "workflow/rules/claims.smk"
include: "workflow/rules/paper.smk"
include: "workflow/rules/study.smk"
include: "workflow/rules/notebooks.smk"
include: "workflow/rules/report.smk"
include: "workflow/rules/docs.smk"
include: "workflow/rules/animation.smk"


rule all:
    default_target: True
    input:
        FIGURES,
        "figures/animation.gif",
        "results/claims.json",
        "results/claims.md",
        "results/claims.html",
        "results/figures.html",
        "paper/paper.pdf",
        STUDY_OUTPUTS,
        NOTEBOOKS,
