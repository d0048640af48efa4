# The claims registry (turntable.claims): every claim of the paper checked against independent
# references, with a verdict. The package is an input, so that editing the physics or a check
# reruns the rule.


rule claims:
    input:
        **notebook_inputs("scripts/claims_report.py"),
    output:
        json=ensure("results/claims.json", non_empty=True),
        md=ensure("results/claims.md", non_empty=True),
        notebook=notebook("claims_report"),
    log:
        "logs/claims.log",
    benchmark:
        "logs/benchmarks/claims.tsv"
    conda:
        "../envs/turntable.yaml"
    params:
        claims=config["claims"],
    script:
        NOTEBOOK_JOB
