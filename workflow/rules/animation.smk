# The animation of the ball on the turntable (figures/animation.gif, Pillow, no ffmpeg): the
# exact solution beside the no-slip limit. Physics in turntable (solve, nonholonomic,
# orientation), drawing in scripts/_style/animation.py; both are inputs, so that editing
# either redraws it. Shown at the top of README.md (docs/animation.gif, rule
# readme_animation in docs.smk) and in the HTML report.

ANIMATION_INPUTS = (
    STYLE_FILES
    + [str(Path(workflow.basedir) / "scripts" / "_style" / "animation.py")]
    + sorted(
        str(p) for p in (Path(workflow.basedir) / "src" / "turntable").rglob("*.py")
    )
)


rule animation:
    input:
        ANIMATION_INPUTS,
    output:
        gif=report(
            "figures/animation.gif",
            caption="../report/animation.rst",
            category="Animation",
        ),
    log:
        "logs/animation.log",
    conda:
        "../envs/turntable.yaml"
    params:
        k=config["animation"]["k"],
        mu0=config["animation"]["mu0"],
        state=config["animation"]["state"],
        wz=config["animation"]["wz"],
        t_end=config["animation"]["t_end"],
        n_frames=config["animation"]["n_frames"],
        substeps=config["animation"]["substeps"],
        frame_ms=config["animation"]["frame_ms"],
        size=config["animation"]["size"],
    script:
        "../../scripts/animation.py"
