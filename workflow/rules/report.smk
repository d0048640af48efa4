# The HTML report (`make report`): every output registered with report(...), under its
# category, with its caption from workflow/report/; and one page with every figure.


report: "../report/workflow.rst"


rule figure_gallery:
    input:
        pngs=expand("figures/{name}.png", name=FIGURES),
        captions=expand("workflow/report/{name}.rst", name=FIGURES),
        animation="figures/animation.gif",
        animation_caption="workflow/report/animation.rst",
        code=[
            *code_inputs(ROOT / "workflow/scripts/figure_gallery.py"),
            "workflow/scripts/report_figure.py",
            "workflow/templates/figure.html.j2",
            "workflow/templates/figures.html.j2",
        ],
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
    conda:
        "../envs/turntable.yaml"
    params:
        names=FIGURES,
    script:
        "../scripts/figure_gallery.py"
