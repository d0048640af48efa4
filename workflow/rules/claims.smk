# The claims registry (turntable.claims): every claim of the paper checked against
# independent references, with a verdict; and its table as a page of the HTML report.


rule claims:
    input:
        **script_inputs("claims_report"),
    output:
        json=ensure("results/claims.json", non_empty=True),
        md=ensure("results/claims.md", non_empty=True),
    log:
        "logs/claims.log",
    benchmark:
        "logs/benchmarks/claims.tsv"
    priority: 1
    conda:
        "../envs/turntable.yaml"
    params:
        claims=config["claims"],
    script:
        "../../scripts/claims_report.py"


rule claims_table:
    input:
        "results/claims.json",
        code=code_inputs(ROOT / "workflow/scripts/claims_table.py"),
    output:
        ensure(
            report(
                "results/claims.html",
                caption="../report/claims.rst",
                category="Claims",
            ),
            non_empty=True,
        ),
    log:
        "logs/claims_table.log",
    conda:
        "../envs/turntable.yaml"
    script:
        "../scripts/claims_table.py"
