# Parameter study of the Section 2 claims over a grid of (k, mu0): one job per inertia ratio
# k (rule study_k, the wildcard), each independent, so that on a cluster (profiles/slurm/)
# every k runs as its own job; rule study gathers them into results/study/summary.json and
# a figure. All physics is in turntable.study.
import re

STUDY_K = [str(k) for k in config["study"]["k"]]
STUDY_OUTPUTS = [
    "results/study/summary.json",
    "results/study/summary.pdf",
    "results/study/summary.png",
]


rule study_k:
    output:
        "results/study/k_{k}.json",
    log:
        "logs/study/k_{k}.log",
    wildcard_constraints:
        k="|".join(re.escape(k) for k in STUDY_K),
    conda:
        "../envs/turntable.yaml"
    params:
        mu0_range=config["study"]["mu0_range"],
        n_points=config["study"]["n_points"],
        state=config["study"]["state"],
        t_span=config["study"]["t_span"],
        n_times=config["study"]["n_times"],
    script:
        "../../scripts/study_k.py"


rule study:
    input:
        results=expand("results/study/k_{k}.json", k=STUDY_K),
        style=STYLE_FILES,
    output:
        json="results/study/summary.json",
        pdf="results/study/summary.pdf",
        png=report(
            "results/study/summary.png",
            caption="../report/study.rst",
            category="Parameter study",
        ),
    log:
        "logs/study/summary.log",
    conda:
        "../envs/turntable.yaml"
    params:
        dpi=config["style"]["dpi"],
    script:
        "../../scripts/study_summary.py"
