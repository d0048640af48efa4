# The HTML report (`make report`, i.e. `snakemake --report results/report.html`): one
# self-contained page with every figure registered with report(...) in the rules, under its
# category, with the caption from workflow/report/<figure>.rst. This file only sets the
# page's introduction.


report: "../report/workflow.rst"


# The claims table with the verdicts, as a page of the HTML report (category "Claims").
rule claims_table:
    input:
        "results/claims.json",
        code=code("workflow/scripts/claims_table.py"),
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
    benchmark:
        "logs/benchmarks/claims_table.tsv"
    conda:
        "../envs/turntable.yaml"
    script:
        "../scripts/claims_table.py"


# The animation and every figure, each with its caption, on one page of the HTML report
# (category "Overview").
rule figure_gallery:
    input:
        pngs=expand("figures/{name}.png", name=FIGURE_NAMES),
        captions=[source(f"workflow/report/{name}.rst") for name in FIGURE_NAMES],
        animation="figures/animation.gif",
        animation_caption=source("workflow/report/animation.rst"),
        code=code("workflow/scripts/figure_gallery.py"),
    output:
        ensure(
            report(
                "results/figures.html",
                caption="../report/figures.rst",
                category="Overview",
            ),
            non_empty=True,
        ),
    log:
        "logs/figure_gallery.log",
    benchmark:
        "logs/benchmarks/figure_gallery.tsv"
    conda:
        "../envs/turntable.yaml"
    params:
        names=FIGURE_NAMES,
    script:
        "../scripts/figure_gallery.py"
