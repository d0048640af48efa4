# A filmed ball: synthetic films of the ball of config section `film` (marked SYNTHETIC),
# fitted with the command `turntable fit` (the package's console script), what the two
# film figures need beyond the loop of figures.smk (Fig. 8, what the camera can measure,
# also writes its numbers; Fig. 9 draws the fits of the synthetic films), and the page
# "What a film can tell" of the HTML report, made from those numbers.
import os
import sys

# The films by name (workflow/config_checks.py has checked that the names differ).
FILM_SPECS = {film["name"]: film for film in config["synthetic_film"]["films"]}
FILMS = list(FILM_SPECS)
FILM_CSV = expand("results/film/{film}.csv", film=FILMS)
FILM_FITS = expand("results/film/{film}.json", film=FILMS)
# The truth of every synthetic film (model, coefficient, start, seed), marked synthetic.
FILM_TRUTH = "results/film/synthetic.json"
FILM_MEASURABILITY = "results/film/measurability.json"
FILM_OUTPUTS = [*FILM_CSV, FILM_TRUTH, *FILM_FITS, FILM_MEASURABILITY]
# What the article's section "What a film can tell" reads (rule paper).
FILM_RESULTS = [FILM_TRUTH, *FILM_FITS, FILM_MEASURABILITY]
FILM_FIGURES = ["fig8_measurability", "fig9_fit"]

FIGURE_EXTRAS["fig8_measurability"] = {
    "output": {"json": ensure("results/film/measurability.json", non_empty=True)},
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
        **notebook_inputs("scripts/synthetic_film.py"),
    output:
        csv=[ensure(path, non_empty=True) for path in FILM_CSV],
        truth=ensure(FILM_TRUTH, non_empty=True),
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
        NOTEBOOK_JOB


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
    # The command's warnings (one line each, exit status 0) go to the log.
    shell:
        "turntable fit {input.csv:q} --radius {params.radius} --rpm {params.rpm} "
        "--k {params.k} --axis {params.axis} --mass {params.mass} > {output:q} 2> {log:q}"


# The page "What a film can tell" of the HTML report (results/film.html): what the camera
# of section film can measure and what the fits of the synthetic films recovered, every
# number read from the results above, with Figures 8 and 9 and their captions.
rule film_page:
    input:
        fits=FILM_FITS,
        truth=FILM_TRUTH,
        measurability=FILM_MEASURABILITY,
        pngs=expand("figures/{name}.png", name=FILM_FIGURES),
        captions=[source(f"workflow/report/{name}.rst") for name in FILM_FIGURES],
        code=code("workflow/scripts/film_page.py"),
    output:
        ensure(
            report(
                "results/film.html",
                caption="../report/film.rst",
                category="What a film can tell",
            ),
            non_empty=True,
        ),
    log:
        "logs/film_page.log",
    benchmark:
        "logs/benchmarks/film_page.tsv"
    conda:
        "../envs/turntable.yaml"
    params:
        names=FILM_FIGURES,
    script:
        "../scripts/film_page.py"
