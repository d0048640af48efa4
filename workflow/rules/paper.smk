# The reproduction article: paper/paper.typ compiled with the typst Python package. Every number
# in it is read from results/claims.json, which the PDF also carries as an attachment.

PAPER_SOURCES = sorted(str(p) for p in Path("paper").glob("*.typ")) + [
    "paper/references.bib"
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
    params:
        main="paper/paper.typ",
        timestamp=config["paper"]["timestamp"],
    script:
        "../../scripts/build_paper.py"
