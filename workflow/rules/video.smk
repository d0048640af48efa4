# From video to friction: a SYNTHETIC video of the ball of section film (section fig10_video),
# tracked by `turntable track` and its track fitted by `turntable fit FILM.csv` (the film and
# its calibration: as the video is fitted, without tracking it again). Its jobs, the campaign's and
# the claims (priority 1) are the longest chains of the build: they start first.
import json

from turntable.campaign import Film, simulation

VIDEO = "results/video/ball_SYNTHETIC.mp4"
VIDEO_TRUTH = "results/video/truth_SYNTHETIC.csv"
VIDEO_TRACK = "results/video/track_SYNTHETIC.csv"
VIDEO_FIT = "results/video/fit_SYNTHETIC.json"
_v = config["fig10_video"]
VIDEO_BALL = Film(
    row=0,
    name="ball_SYNTHETIC",
    path=VIDEO,
    **{key: config["film"][key] for key in ("radius_m", "k", "rpm")},
    platter_radius_m=_v["platter_radius_m"],
    labels={
        "true_model": _v["model"],
        "true_value": str(_v["coefficient"]),
        "seed": str(_v["seed"]),
    },
    synthetic=True,
)


rule render_video:
    input:
        code=CAMPAIGN_CODE,
    output:
        video=ensure(VIDEO, non_empty=True),
        truth=ensure(VIDEO_TRUTH, non_empty=True),
    log:
        "logs/render_video.log",
    benchmark:
        "logs/benchmarks/render_video.tsv"
    priority: 1
    conda:
        "../envs/turntable.yaml"
    params:
        spec=json.dumps(simulation(VIDEO_BALL, config["film"], config["fig10_video"])),
    shell:
        "python -m turntable.campaign simulate {params.spec:q} {output.video:q} "
        "{output.truth:q} 2> {log:q}"


rule track_video:
    input:
        video=VIDEO,
        code=CLI,
    output:
        csv=ensure(VIDEO_TRACK, non_empty=True),
        json=ensure(VIDEO_TRACK.replace(".csv", ".json"), non_empty=True),
    log:
        "logs/track_video.log",
    priority: 1
    conda:
        "../envs/turntable.yaml"
    params:
        radius=config["film"]["radius_m"],
        platter=config["fig10_video"]["platter_radius_m"],
        rpm=config["film"]["rpm"],
    shell:
        "turntable track {input.video:q} --ball-radius {params.radius} "
        "--platter-radius {params.platter} --rpm {params.rpm} -o {output.csv:q} > {log:q} 2>&1"


rule fit_video:
    input:
        track=VIDEO_TRACK,
        calibration=VIDEO_TRACK.replace(".csv", ".json"),
        code=CLI,
    output:
        ensure(VIDEO_FIT, non_empty=True),
    log:
        "logs/fit_video.log",
    priority: 1
    conda:
        "../envs/turntable.yaml"
    params:
        radius=config["film"]["radius_m"],
        k=config["film"]["k"],
    shell:
        "turntable fit {input.track:q} --radius {params.radius} --k {params.k} > {output:q} "
        "2> {log:q}"
