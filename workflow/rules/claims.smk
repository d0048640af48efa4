# The claims registry (turntable.claims): every claim of the paper checked against independent
# references, with a verdict. The package sources are inputs, so that editing the physics or
# a check re-runs the rule.

CLAIMS_SOURCES = sorted(str(p) for p in Path("src/turntable").rglob("*.py"))


rule claims:
    input:
        CLAIMS_SOURCES,
    output:
        json="results/claims.json",
        md="results/claims.md",
    log:
        "logs/claims.log",
    params:
        claims=config["claims"],
    script:
        "../../scripts/claims_report.py"
