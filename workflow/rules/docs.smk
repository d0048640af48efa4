# The figure shown in README.md, docs/fig4_trajectories.png: a copy of the pipeline's own
# figures/fig4_trajectories.png, refreshed by `make readme-figure` (target readme_figure,
# not part of the default target, since docs/ is committed). tests/test_readme.py checks
# that the committed copy has the same bytes as a fresh build of the figure.


rule readme_figure:
    input:
        "figures/fig4_trajectories.png",
    output:
        ensure("docs/fig4_trajectories.png", non_empty=True),
    log:
        "logs/readme_figure.log",
    localrule: True
    conda:
        "../envs/turntable.yaml"
    shell:
        "cp {input:q} {output:q} && echo 'copied {input} to {output}' > {log:q}"


# The animation at the top of README.md, docs/animation.gif: a copy of figures/animation.gif,
# refreshed by `make readme-figure` like the figure above, byte-compared by tests/test_readme.py.
rule readme_animation:
    input:
        "figures/animation.gif",
    output:
        ensure("docs/animation.gif", non_empty=True),
    log:
        "logs/readme_animation.log",
    localrule: True
    conda:
        "../envs/turntable.yaml"
    shell:
        "cp {input:q} {output:q} && echo 'copied {input} to {output}' > {log:q}"
