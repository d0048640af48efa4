# The HTML report (`make report`, i.e. `snakemake --report results/report.html`): one
# self-contained page with every figure registered with report(...) in the rules, under its
# category, with the caption from workflow/report/<figure>.rst. This file only sets the
# page's introduction.


report: "../report/workflow.rst"


# The claims table with the verdicts, as a page of the HTML report (category "Claims").
rule claims_table:
    input:
        "results/claims.json",
    output:
        report(
            "results/claims.html",
            caption="../report/claims.rst",
            category="Claims",
        ),
    log:
        "logs/claims_table.log",
    conda:
        "../envs/turntable.yaml"
    script:
        "../scripts/claims_table.py"


# Every figure with its caption on one page of the HTML report (category "Overview").
rule figure_gallery:
    input:
        pngs=expand("figures/{name}.png", name=FIGURE_NAMES),
        captions=expand(
            str(Path(workflow.basedir) / "workflow" / "report" / "{name}.rst"),
            name=FIGURE_NAMES,
        ),
    output:
        report(
            "results/figures.html",
            caption="../report/figures.rst",
            category="Overview",
        ),
    log:
        "logs/figure_gallery.log",
    conda:
        "../envs/turntable.yaml"
    params:
        names=FIGURE_NAMES,
    script:
        "../scripts/figure_gallery.py"
