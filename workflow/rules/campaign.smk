# A campaign of films (section campaign): one job per film of the table fits it with
# turntable fit (a film it refuses is recorded, not fatal); one job gathers the fits into
# results/campaign/summary.csv and a figure. The table's SYNTHETIC films are written here,
# one job each.
import json
import re
from dataclasses import asdict

from turntable.campaign import CampaignError, read_table, simulation

try:
    CAMPAIGN, CAMPAIGN_BAD_ROWS = read_table(
        config["campaign"]["table"], group_by=config["campaign"]["group_by"]
    )
except CampaignError as exc:
    raise WorkflowError(f"campaign: {exc}") from None
CAMPAIGN_FILMS = {film.name: film for film in CAMPAIGN}
CAMPAIGN_SYNTHETIC = {Path(f.path).name: f for f in CAMPAIGN if f.synthetic}
CAMPAIGN_OUTPUTS = expand("results/campaign/summary.{ext}", ext=["csv", "pdf", "png"])


rule campaign_film:
    input:
        code=PACKAGE,
    output:
        ensure("results/campaign/films/{film}", non_empty=True),
    log:
        "logs/campaign/{film}.simulate.log",
    wildcard_constraints:
        film="|".join(map(re.escape, CAMPAIGN_SYNTHETIC)) or "^$",
    conda:
        "../envs/turntable.yaml"
    params:
        spec=lambda w: json.dumps(
            simulation(
                CAMPAIGN_SYNTHETIC[w.film], config["film"], config["fig10_video"]
            )
        ),
    shell:
        "python -m turntable.campaign simulate {params.spec:q} {output:q} 2> {log:q}"


rule campaign_fit:
    input:
        film=lambda w: CAMPAIGN_FILMS[w.film].path,
        code=PACKAGE,
    output:
        ensure("results/campaign/fits/{film}.json", non_empty=True),
    log:
        "logs/campaign/{film}.log",
    wildcard_constraints:
        film="|".join(CAMPAIGN_FILMS) or "^$",
    group:
        "campaign"
    conda:
        "../envs/turntable.yaml"
    params:
        args=lambda w: json.dumps(CAMPAIGN_FILMS[w.film].fit_args()),
    shell:
        "python -m turntable.campaign fit {params.args:q} {output:q} 2> {log:q}"


rule campaign:
    input:
        **script_inputs("campaign_summary", STYLE),
        fits=expand("results/campaign/fits/{film}.json", film=CAMPAIGN_FILMS),
    output:
        csv=ensure("results/campaign/summary.csv", non_empty=True),
        pdf=ensure("results/campaign/summary.pdf", non_empty=True),
        png=ensure(
            report(
                "results/campaign/summary.png",
                caption="../report/campaign.rst",
                category="Campaign",
            ),
            non_empty=True,
        ),
    log:
        "logs/campaign/summary.log",
    conda:
        "../envs/turntable.yaml"
    params:
        films={name: asdict(film) for name, film in CAMPAIGN_FILMS.items()},
        bad_rows=CAMPAIGN_BAD_ROWS,
        group_by=config["campaign"]["group_by"],
        table=config["campaign"]["table"],
        dpi=config["style"]["dpi"],
    script:
        "../../scripts/campaign_summary.py"
