# The animation of the ball on the turntable (figures/animation.gif, Pillow, no ffmpeg): the
# exact solution beside the no-slip limit. Physics in turntable (solve, nonholonomic,
# orientation), drawing in scripts/_style/animation.py; both are inputs, so that editing
# either redraws it. Shown at the top of README.md (docs/animation.gif, rule
# readme_animation in docs.smk) and in the HTML report.


rule animation:
    input:
        **notebook_inputs("scripts/animation.py"),
    output:
        gif=ensure(
            report(
                "figures/animation.gif",
                caption="../report/animation.rst",
                category="Animation",
            ),
            non_empty=True,
        ),
        notebook=notebook("animation"),
    log:
        "logs/animation.log",
    benchmark:
        "logs/benchmarks/animation.tsv"
    conda:
        "../envs/turntable.yaml"
    params:
        **config["animation"],
    script:
        NOTEBOOK_JOB
