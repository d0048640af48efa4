# The reproduction article: paper/paper.typ compiled with the typst Python package. Every number
# in it is read from results/claims.json, which the PDF also carries as an attachment. The
# sources are taken from the repository (workflow.basedir); the script compiles a copy of the
# inputs, so that the rule also runs with --directory elsewhere.

PAPER_DIR = Path(workflow.basedir) / "paper"
PAPER_SOURCES = sorted(str(p) for p in PAPER_DIR.glob("*.typ")) + [
    str(PAPER_DIR / "references.bib")
]


rule paper:
    input:
        sources=PAPER_SOURCES,
        claims="results/claims.json",
        figures=FIGURES,
    output:
        "paper/paper.pdf",
    log:
        "logs/paper.log",
    conda:
        "../envs/turntable.yaml"
    params:
        main="paper.typ",
        timestamp=config["paper"]["timestamp"],
        repository=config["paper"]["repository"],
    script:
        "../../scripts/build_paper.py"
