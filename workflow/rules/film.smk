# A filmed ball: synthetic films of the ball of config section `film` (marked SYNTHETIC),
# fitted with the command `turntable fit` (the package's console script), and what the two
# film figures need beyond the loop of figures.smk (Fig. 8, what the camera can measure,
# also writes its numbers; Fig. 9 draws the fits of the synthetic films).
import os
import sys

# The films by name (workflow/config_checks.py has checked that the names differ).
FILM_SPECS = {film["name"]: film for film in config["synthetic_film"]["films"]}
FILMS = list(FILM_SPECS)
FILM_CSV = expand("results/film/{film}.csv", film=FILMS)
FILM_FITS = expand("results/film/{film}.json", film=FILMS)
FILM_OUTPUTS = [*FILM_CSV, *FILM_FITS, "results/film/measurability.json"]

FIGURE_EXTRAS["fig8_measurability"] = {
    "output": {"json": "results/film/measurability.json"},
    "params": {"film": config["film"]},
}
FIGURE_EXTRAS["fig9_fit"] = {
    "input": {"csv": FILM_CSV, "json": FILM_FITS},
    "params": {"films": FILM_SPECS},
}


# `turntable fit` runs from the environment that runs Snakemake (the project's .venv), or
# from the rule's conda environment with --sdm conda, which Snakemake puts first on PATH.
# Set here rather than in the command, so that the command stays the same wherever the
# environment lies. (PATH is declared, so that Snakemake passes it on to remote jobs.)
envvars:
    "PATH",


os.environ["PATH"] = os.pathsep.join(
    [str(Path(sys.executable).parent), os.environ["PATH"]]
)


rule synthetic_film:
    input:
        code=PACKAGE,
        script=source("scripts/synthetic_film.py"),
    output:
        csv=[ensure(path, non_empty=True) for path in FILM_CSV],
        notebook=notebook("synthetic_film"),
    log:
        "logs/synthetic_film.log",
    benchmark:
        "logs/benchmarks/synthetic_film.tsv"
    conda:
        "../envs/turntable.yaml"
    params:
        film=config["film"],
        films=FILM_SPECS,
    script:
        NOTEBOOK_DRIVER


rule fit_film:
    input:
        csv="results/film/{film}.csv",
        code=PACKAGE,
    output:
        ensure("results/film/{film}.json", non_empty=True),
    log:
        "logs/fit_film/{film}.log",
    benchmark:
        "logs/benchmarks/fit_film_{film}.tsv"
    wildcard_constraints:
        film="|".join(FILMS),
    conda:
        "../envs/turntable.yaml"
    params:
        radius=config["film"]["radius_m"],
        rpm=config["film"]["rpm"],
        k=config["film"]["k"],
        axis=" ".join(str(a) for a in config["film"]["axis_m"]),
        mass=config["film"]["mass_kg"],
    shell:
        "turntable fit {input.csv:q} --radius {params.radius} --rpm {params.rpm} "
        "--k {params.k} --axis {params.axis} --mass {params.mass} > {output:q} 2> {log:q}"
