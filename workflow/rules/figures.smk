# One rule per figure, generated from the list in workflow/figures.yaml. Each rule runs
# scripts/<name>.py once, as a notebook, with the section <name> of config/config.yaml as its
# parameters (with the resolution of the style, and what FIGURE_EXTRAS of common.smk adds),
# so that editing a value reruns only the figures that read it.
import yaml

FIGURE_NAMES = yaml.safe_load(Path(workflow.basedir, "figures.yaml").read_text())
FIGURES = expand("figures/{name}.{ext}", name=FIGURE_NAMES, ext=["pdf", "png"])


for name in FIGURE_NAMES:

    rule:
        name:
            name
        input:
            **FIGURE_EXTRAS.get(name, {}).get("input", {}),
            **notebook_inputs(f"scripts/{name}.py"),
        output:
            **FIGURE_EXTRAS.get(name, {}).get("output", {}),
            pdf=ensure(f"figures/{name}.pdf", non_empty=True),
            png=ensure(
                report(
                    f"figures/{name}.png",
                    caption=f"../report/{name}.rst",
                    category="Figures",
                ),
                non_empty=True,
            ),
            notebook=notebook(name),
        log:
            f"logs/{name}.log",
        benchmark:
            f"logs/benchmarks/{name}.tsv"
        conda:
            "../envs/turntable.yaml"
        params:
            **config.get(name, {}),
            **FIGURE_EXTRAS.get(name, {}).get("params", {}),
            dpi=config["style"]["dpi"],
        script:
            NOTEBOOK_JOB


rule figures:
    input:
        FIGURES,
