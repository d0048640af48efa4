# One rule per figure. Each passes its parameters as `params:` so that editing a value in
# config/config.yaml reruns only the figures that read it.

FIGURE_NAMES = [
    "fig1_schematic",
    "fig2_spectrum",
    "fig3_modal_terms",
    "fig4_trajectories",
    "fig5_damping_ratio",
    "fig6_limit",
    "fig7_rolling_resistance",
]
FIGURES = expand("figures/{name}.{ext}", name=FIGURE_NAMES, ext=["pdf", "png"])


rule fig1_schematic:
    input:
        STYLE_FILES,
    output:
        pdf="figures/fig1_schematic.pdf",
        png=report(
            "figures/fig1_schematic.png",
            caption="../report/fig1_schematic.rst",
            category="Figures",
        ),
    log:
        "logs/fig1_schematic.log",
    conda:
        "../envs/turntable.yaml"
    params:
        dpi=config["style"]["dpi"],
        tilt=config["fig1_schematic"]["tilt"],
    script:
        "../../scripts/fig1_schematic.py"


rule fig2_spectrum:
    input:
        STYLE_FILES,
    output:
        pdf="figures/fig2_spectrum.pdf",
        png=report(
            "figures/fig2_spectrum.png",
            caption="../report/fig2_spectrum.rst",
            category="Figures",
        ),
    log:
        "logs/fig2_spectrum.log",
    conda:
        "../envs/turntable.yaml"
    params:
        dpi=config["style"]["dpi"],
        k=config["fig2_spectrum"]["k"],
        mu0_range=config["fig2_spectrum"]["mu0_range"],
        n_points=config["fig2_spectrum"]["n_points"],
    script:
        "../../scripts/fig2_spectrum.py"


rule fig3_modal_terms:
    input:
        STYLE_FILES,
    output:
        pdf="figures/fig3_modal_terms.pdf",
        png=report(
            "figures/fig3_modal_terms.png",
            caption="../report/fig3_modal_terms.rst",
            category="Figures",
        ),
    log:
        "logs/fig3_modal_terms.log",
    conda:
        "../envs/turntable.yaml"
    params:
        dpi=config["style"]["dpi"],
        k=config["fig3_modal_terms"]["k"],
        mu0=config["fig3_modal_terms"]["mu0"],
        state=config["fig3_modal_terms"]["state"],
        t_span=config["fig3_modal_terms"]["t_span"],
        n_points=config["fig3_modal_terms"]["n_points"],
    script:
        "../../scripts/fig3_modal_terms.py"


rule fig4_trajectories:
    input:
        STYLE_FILES,
    output:
        pdf="figures/fig4_trajectories.pdf",
        png=report(
            "figures/fig4_trajectories.png",
            caption="../report/fig4_trajectories.rst",
            category="Figures",
        ),
    log:
        "logs/fig4_trajectories.log",
    conda:
        "../envs/turntable.yaml"
    params:
        dpi=config["style"]["dpi"],
        k=config["fig4_trajectories"]["k"],
        state=config["fig4_trajectories"]["state"],
        mu0=config["fig4_trajectories"]["mu0"],
        t_span=config["fig4_trajectories"]["t_span"],
        n_points=config["fig4_trajectories"]["n_points"],
    script:
        "../../scripts/fig4_trajectories.py"


rule fig5_damping_ratio:
    input:
        STYLE_FILES,
    output:
        pdf="figures/fig5_damping_ratio.pdf",
        png=report(
            "figures/fig5_damping_ratio.png",
            caption="../report/fig5_damping_ratio.rst",
            category="Figures",
        ),
    log:
        "logs/fig5_damping_ratio.log",
    conda:
        "../envs/turntable.yaml"
    params:
        dpi=config["style"]["dpi"],
        k=config["fig5_damping_ratio"]["k"],
        mu0_range=config["fig5_damping_ratio"]["mu0_range"],
        n_points=config["fig5_damping_ratio"]["n_points"],
    script:
        "../../scripts/fig5_damping_ratio.py"


rule fig6_limit:
    input:
        STYLE_FILES,
    output:
        pdf="figures/fig6_limit.pdf",
        png=report(
            "figures/fig6_limit.png",
            caption="../report/fig6_limit.rst",
            category="Figures",
        ),
    log:
        "logs/fig6_limit.log",
    conda:
        "../envs/turntable.yaml"
    params:
        dpi=config["style"]["dpi"],
        k=config["fig6_limit"]["k"],
        state=config["fig6_limit"]["state"],
        mu0_trajectories=config["fig6_limit"]["mu0_trajectories"],
        mu0_error_range=config["fig6_limit"]["mu0_error_range"],
        n_error=config["fig6_limit"]["n_error"],
        n_points=config["fig6_limit"]["n_points"],
        layer_state=config["fig6_limit"]["layer_state"],
        mu0_layer=config["fig6_limit"]["mu0_layer"],
        layer_t_span=config["fig6_limit"]["layer_t_span"],
    script:
        "../../scripts/fig6_limit.py"


rule fig7_rolling_resistance:
    input:
        STYLE_FILES,
        sorted(
            str(f)
            for f in (Path(workflow.basedir) / "src" / "turntable").rglob("*.py")
        ),
    output:
        pdf="figures/fig7_rolling_resistance.pdf",
        png=report(
            "figures/fig7_rolling_resistance.png",
            caption="../report/fig7_rolling_resistance.rst",
            category="Figures",
        ),
    log:
        "logs/fig7_rolling_resistance.log",
    conda:
        "../envs/turntable.yaml"
    params:
        dpi=config["style"]["dpi"],
        k=config["fig7_rolling_resistance"]["k"],
        state=config["fig7_rolling_resistance"]["state"],
        mu0=config["fig7_rolling_resistance"]["mu0"],
        comparison=config["fig7_rolling_resistance"]["comparison"],
        t_span=config["fig7_rolling_resistance"]["t_span"],
        n_points=config["fig7_rolling_resistance"]["n_points"],
        mu0_range=config["fig7_rolling_resistance"]["mu0_range"],
        n_grid=config["fig7_rolling_resistance"]["n_grid"],
    script:
        "../../scripts/fig7_rolling_resistance.py"


rule figures:
    input:
        FIGURES,
