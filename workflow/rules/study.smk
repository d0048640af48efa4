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
    input:
        **notebook_inputs("scripts/study_k.py"),
    output:
        json=ensure("results/study/k_{k}.json", non_empty=True),
        notebook=notebook("study_k_{k}", k=STUDY_K),
    log:
        "logs/study/k_{k}.log",
    benchmark:
        "logs/benchmarks/study_k_{k}.tsv"
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
        NOTEBOOK_JOB


rule study:
    input:
        **notebook_inputs("scripts/study_summary.py"),
        results=expand("results/study/k_{k}.json", k=STUDY_K),
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
        notebook=notebook("study_summary"),
    log:
        "logs/study/summary.log",
    benchmark:
        "logs/benchmarks/study.tsv"
    conda:
        "../envs/turntable.yaml"
    params:
        dpi=config["style"]["dpi"],
    script:
        NOTEBOOK_JOB
