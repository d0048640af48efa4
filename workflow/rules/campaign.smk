# A campaign of films (section campaign): one job per batch of batch_size films of the table
# fits them with turntable fit, in one process (a film it refuses is recorded, not fatal);
# one job gathers the fits into results/campaign/summary.csv and a figure. The table's
# SYNTHETIC films are written here, one job each.
import json
import re
from dataclasses import asdict

from turntable.campaign import (
    CampaignError,
    batches,
    group_column,
    read_table,
    simulation,
)

try:
    CAMPAIGN, CAMPAIGN_BAD_ROWS = read_table(
        config["campaign"]["table"], group_by=config["campaign"]["group_by"]
    )
except CampaignError as exc:
    raise WorkflowError(f"campaign: {exc}") from None
CAMPAIGN_FILMS = {film.name: film for film in CAMPAIGN}
# The label that groups the films (the first label column unless set), also for the caption.
config["campaign"]["group_by"] = group_column(CAMPAIGN, config["campaign"]["group_by"])
# A change to a row reruns its batch only (the films, in the table's order, cut in batches).
CAMPAIGN_BATCHES = batches(list(CAMPAIGN_FILMS), config["campaign"]["batch_size"])
CAMPAIGN_SYNTHETIC = {Path(f.path).name: f for f in CAMPAIGN if f.synthetic}
CAMPAIGN_OUTPUTS = expand("results/campaign/summary.{ext}", ext=["csv", "pdf", "png"])


rule campaign_film:
    input:
        code=CAMPAIGN_CODE,
    output:
        ensure("results/campaign/films/{film}", non_empty=True),
    log:
        "logs/campaign/{film}.simulate.log",
    wildcard_constraints:
        film="|".join(map(re.escape, CAMPAIGN_SYNTHETIC)) or "^$",
    priority: 1
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
        films=lambda w: [CAMPAIGN_FILMS[f].path for f in CAMPAIGN_BATCHES[w.batch]],
        code=CAMPAIGN_CODE,
    output:
        ensure("results/campaign/fits/batch_{batch}.json", non_empty=True),
    log:
        "logs/campaign/batch_{batch}.log",
    wildcard_constraints:
        batch="|".join(CAMPAIGN_BATCHES) or "^$",
    priority: 1
    conda:
        "../envs/turntable.yaml"
    params:
        args=lambda w: json.dumps(
            {f: CAMPAIGN_FILMS[f].fit_options() for f in CAMPAIGN_BATCHES[w.batch]}
        ),
    shell:
        "python -m turntable.campaign fit {params.args:q} {output:q} 2> {log:q}"


rule campaign:
    input:
        **script_inputs("campaign_summary", STYLE),
        fits=expand("results/campaign/fits/batch_{batch}.json", batch=CAMPAIGN_BATCHES),
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
