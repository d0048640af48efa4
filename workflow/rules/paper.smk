# The reproduction article: paper/paper.typ compiled with the typst Python package. Every number
# in it is read from results/claims.json, which the PDF also carries as an attachment, or, in
# the section "What a film can tell" (paper/film.typ), from the fits of the synthetic films and
# the measurability of the camera (results/film/, FILM_RESULTS of film.smk). The script
# compiles a copy of the inputs, so that the rule also runs with --directory elsewhere.

PAPER_SOURCES = sorted(
    source(p) for p in ["paper/references.bib", *ROOT.glob("paper/*.typ")]
)


rule paper:
    input:
        **notebook_inputs("scripts/build_paper.py"),
        sources=PAPER_SOURCES,
        claims="results/claims.json",
        film=FILM_RESULTS,
        figures=FIGURES,
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
        main="paper.typ",
        timestamp=config["paper"]["timestamp"],
        repository=config["paper"]["repository"],
        # not read by the script (it records its own provenance): reruns the job when the
        # commit or the dirty state changes
        git_state=GIT_STATE,
        config_overrides=CONFIG_OVERRIDES,
    script:
        NOTEBOOK_JOB
