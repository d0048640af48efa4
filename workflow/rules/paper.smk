# The reproduction article: paper/paper.typ compiled with the typst Python package. Every
# number in it is read from results/claims.json and the results of the films.
import glob


rule paper:
    input:
        **script_inputs("build_paper"),
        sources=sorted(glob.glob("paper/*.typ") + ["paper/references.bib"]),
        claims="results/claims.json",
        film=[FILM_TRUTH, *FILM_FITS, FILM_MEASURABILITY],
        figures=expand("figures/{name}.{ext}", name=FIGURES, ext=["pdf", "png"]),
    output:
        pdf=ensure("paper/paper.pdf", non_empty=True),
        notebook=notebook("build_paper"),
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
        "../scripts/as_notebook.py"
