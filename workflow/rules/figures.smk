# One rule per figure of workflow/figures.yaml: scripts/<name>.py, run with the
# section <name> of the configuration as its params, writes figures/<name>.{pdf,png}; its
# caption is workflow/report/<name>.rst. What a figure reads beyond its own section:
EXTRA = {
    "fig6_limit": {"params": {"claims": config["claims"]}},
    "fig7_rolling_resistance": {"params": {"claims": config["claims"]}},
    "fig8_measurability": {
        "params": {"film": config["film"]},
        "output": {"json": ensure(FILM_MEASURABILITY, non_empty=True)},
    },
    "fig9_fit": {
        "params": {"films": FILM_SPECS},
        "input": {"csv": FILM_CSV, "json": FILM_FITS},
    },
    "fig10_video": {
        "params": {"film": config["film"]},
        "input": {
            "video": VIDEO,
            "truth": VIDEO_TRUTH,
            "track": VIDEO_TRACK,
            "calibration": VIDEO_TRACK.replace(".csv", ".json"),
            "fit": VIDEO_FIT,
        },
    },
}


for name in FIGURES:

    rule:
        name:
            name
        input:
            **script_inputs(name, STYLE),
            **EXTRA.get(name, {}).get("input", {}),
        output:
            **EXTRA.get(name, {}).get("output", {}),
            pdf=ensure(f"figures/{name}.pdf", non_empty=True),
            png=ensure(
                report(
                    f"figures/{name}.png",
                    caption=f"../report/{name}.rst",
                    category="Figures",
                ),
                non_empty=True,
            ),
        log:
            f"logs/{name}.log",
        benchmark:
            f"logs/benchmarks/{name}.tsv"
        conda:
            "../envs/turntable.yaml"
        params:
            **config.get(name, {}),
            **EXTRA.get(name, {}).get("params", {}),
            dpi=config["style"]["dpi"],
            script=name,  # (a script: path is formatted when the job runs, after the loop)
        script:
            "../../scripts/{params.script}.py"


rule figures:
    input:
        expand("figures/{name}.{ext}", name=FIGURES, ext=["pdf", "png"]),


# The animation of the ball on the turntable, beside its no-slip limit (Pillow, no ffmpeg).
rule animation:
    input:
        **script_inputs("animation", [*STYLE, "scripts/_style/animation.py"]),
    output:
        gif=ensure(
            report(
                "figures/animation.gif",
                caption="../report/animation.rst",
                category="Animation",
            ),
            non_empty=True,
        ),
    log:
        "logs/animation.log",
    benchmark:
        "logs/benchmarks/animation.tsv"
    conda:
        "../envs/turntable.yaml"
    params:
        **config["animation"],
    script:
        "../../scripts/animation.py"


# The pictures of README.md and of the documentation (docs/, committed): `make readme-figure`.
rule readme_figure:
    input:
        png="figures/fig4_trajectories.png",
        gif="figures/animation.gif",
        video="figures/fig10_video.png",
    output:
        png="docs/fig4_trajectories.png",
        gif="docs/animation.gif",
        video="docs/fig10_video.png",
    log:
        "logs/readme_figure.log",
    localrule: True
    conda:
        "../envs/turntable.yaml"
    shell:
        "(cp -v {input.png:q} {output.png:q} && cp -v {input.gif:q} {output.gif:q} "
        "&& cp -v {input.video:q} {output.video:q}) > {log:q}"
