# A filmed ball: synthetic films of the ball of section `film` (marked SYNTHETIC), each
# fitted by `turntable fit`, and the page "What a film can tell" of the HTML report.
import os
import sys

FILM_SPECS = {film["name"]: film for film in config["synthetic_film"]["films"]}
FILM_CSV = expand("results/film/{film}.csv", film=FILM_SPECS)
FILM_FITS = expand("results/film/{film}.json", film=FILM_SPECS)
FILM_TRUTH = "results/film/synthetic.json"
FILM_MEASURABILITY = "results/film/measurability.json"


# `turntable fit` from the environment that runs Snakemake (PATH passed on to remote jobs).
envvars:
    "PATH",


os.environ["PATH"] = os.pathsep.join(
    [os.path.dirname(sys.executable), os.environ["PATH"]]
)


rule synthetic_film:
    input:
        **script_inputs("synthetic_film"),
    output:
        csv=[ensure(path, non_empty=True) for path in FILM_CSV],
        truth=ensure(FILM_TRUTH, non_empty=True),
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
        "../../scripts/synthetic_film.py"


rule fit_film:
    input:
        csv="results/film/{film}.csv",
        code=CLI,
    output:
        ensure("results/film/{film}.json", non_empty=True),
    log:
        "logs/fit_film/{film}.log",
    benchmark:
        "logs/benchmarks/fit_film_{film}.tsv"
    wildcard_constraints:
        film="|".join(FILM_SPECS),
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


rule film_page:
    input:
        fits=FILM_FITS,
        truth=FILM_TRUTH,
        measurability=FILM_MEASURABILITY,
        pngs=expand("figures/{name}.png", name=["fig8_measurability", "fig9_fit"]),
        captions=expand(
            "workflow/report/{name}.rst", name=["fig8_measurability", "fig9_fit"]
        ),
        code=[
            *code_inputs(ROOT / "workflow/scripts/film_page.py"),
            "workflow/scripts/report_figure.py",
            "workflow/templates/figure.html.j2",
        ],
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
    conda:
        "../envs/turntable.yaml"
    params:
        names=["fig8_measurability", "fig9_fit"],
    script:
        "../scripts/film_page.py"
