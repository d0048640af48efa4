# Parameter study of the Section 2 claims over a grid of (k, mu0): one job per inertia ratio
# k (on a cluster, each its own job), gathered into results/study/summary.json and a figure.
import re

# Each inertia ratio by the name of its files, to six significant digits (k_0.666667).
STUDY_K = {f"{k:.6g}": k for k in config["study"]["k"]}
STUDY_OUTPUTS = expand("results/study/summary.{ext}", ext=["json", "pdf", "png"])


rule study_k:
    input:
        **script_inputs("study_k"),
    output:
        json=ensure("results/study/k_{k}.json", non_empty=True),
    log:
        "logs/study/k_{k}.log",
    benchmark:
        "logs/benchmarks/study_k_{k}.tsv"
    wildcard_constraints:
        k="|".join(re.escape(name) for name in STUDY_K),
    conda:
        "../envs/turntable.yaml"
    params:
        **{key: value for key, value in config["study"].items() if key != "k"},
        k=lambda wildcards: STUDY_K[wildcards.k],
    script:
        "../../scripts/study_k.py"


rule study:
    input:
        **script_inputs("study_summary", STYLE),
        results=expand("results/study/k_{k}.json", k=list(STUDY_K)),
    output:
        json=ensure("results/study/summary.json", non_empty=True),
        pdf=ensure("results/study/summary.pdf", non_empty=True),
        png=ensure(
            report(
                "results/study/summary.png",
                caption="../report/study.rst",
                category="Parameter study",
            ),
            non_empty=True,
        ),
    log:
        "logs/study/summary.log",
    benchmark:
        "logs/benchmarks/study.tsv"
    conda:
        "../envs/turntable.yaml"
    params:
        dpi=config["style"]["dpi"],
    script:
        "../../scripts/study_summary.py"
