# The claims registry (turntable.claims): every claim of the paper checked against independent
# references, with a verdict. The package sources are inputs, so that editing the physics or
# a check re-runs the rule. Paths of sources are taken from the repository (workflow.basedir),
# so that the rule also runs with --directory elsewhere.

CLAIMS_SOURCES = sorted(
    str(p)
    for pattern in ("*.py", "*.yaml")
    for p in (Path(workflow.basedir) / "src" / "turntable").rglob(pattern)
)


rule claims:
    input:
        CLAIMS_SOURCES,
    output:
        json="results/claims.json",
        md="results/claims.md",
    log:
        "logs/claims.log",
    conda:
        "../envs/turntable.yaml"
    params:
        claims=config["claims"],
    script:
        "../../scripts/claims_report.py"
