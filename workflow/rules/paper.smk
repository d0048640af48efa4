# The reproduction article: paper/paper.typ compiled with the typst Python package. Every
# number in it is read from results/claims.json; it shows the figures its text names.
import glob
import re

ARTICLE_FIGURES = [
    name
    for name in FIGURES
    if re.search(rf"figures/{name}\.pdf", (ROOT / "paper" / "paper.typ").read_text())
]


rule paper:
    input:
        **script_inputs("build_paper"),
        sources=sorted(glob.glob("paper/*.typ") + ["paper/references.bib"]),
        claims="results/claims.json",
        figures=expand("figures/{name}.pdf", name=ARTICLE_FIGURES),
    output:
        pdf=ensure("paper/paper.pdf", non_empty=True),
    log:
        "logs/paper.log",
    benchmark:
        "logs/benchmarks/paper.tsv"
    conda:
        "../envs/turntable.yaml"
    params:
        **config["paper"],
        # read by the article: the commit that built it, and the values of its own
        main="paper.typ",
        git_state=GIT_STATE,
        config_overrides=OVERRIDES,
    script:
        "../../scripts/build_paper.py"
