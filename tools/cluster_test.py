"""Run the workflow on a real SLURM cluster of one node, started on this machine.

1. Starts munged, slurmctld and slurmd (Debian's slurm-wlm) with every file in a temporary
   directory (``SLURM_CONF``), no accounting database.
2. Builds ``TARGETS`` twice, in two copies of the sources: locally (``--cores``) and
   through ``profiles/slurm``, where every job goes through ``sbatch``, one CPU each (the
   campaign's films in batches of ``campaign.batch_size``, one job per batch). Reads each
   job id back from SLURM (``scontrol show job``: COMPLETED) and compares the outputs byte
   for byte.
3. Removes one result of the study, cancels the job that rebuilds it with ``scancel``,
   checks that Snakemake reports the job as failed, and that a second run finishes with the
   same bytes.
4. Stops the daemons and removes the directory, also when a step fails.

Usage (as root, with slurm-wlm and munge installed; ``make cluster-test`` installs them):
``python tools/cluster_test.py [--keep DIR]``. Prints one line per step, with times.
"""

from __future__ import annotations

import argparse
import filecmp
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))
SOURCES = ["config", "workflow", "scripts", "paper", "src", "profiles"]
TARGETS = ["study", "campaign"]
OUTPUTS = ["results/study", "results/campaign"]
SLURM_FLAGS = [
    "--profile",
    "profiles/slurm",
    "--slurm-status-command",
    "squeue",
    "--slurm-no-account",
    "--slurm-init-seconds-before-status-checks",
    "2",
    "--seconds-between-status-checks",
    "2",
    "--latency-wait",
    "5",
    "--retries",
    "0",
    "--default-resources",
    "slurm_partition=debug",
    "runtime=15",
    "mem_mb=500",
    "cpus_per_task=1",
]
SLURM_CONF = """\
ClusterName=turntable
SlurmctldHost={host}
AuthType=auth/munge
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation={dir}/state
SlurmdSpoolDir={dir}/spool
SlurmctldPidFile={dir}/slurmctld.pid
SlurmdPidFile={dir}/slurmd.pid
SlurmctldLogFile={dir}/slurmctld.log
SlurmdLogFile={dir}/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
MinJobAge=300
SlurmctldParameters=enable_configless
ReturnToService=2
NodeName={host} CPUs={cpus} RealMemory={mem_mb} State=UNKNOWN
PartitionName=debug Nodes={host} Default=YES MaxTime=INFINITE State=UP
"""
START = time.perf_counter()


def say(text: str) -> None:
    print(f"cluster-test [{time.perf_counter() - START:5.1f} s] {text}", flush=True)


def run(*cmd: str, cwd: Path | None = None, check: bool = True) -> subprocess.CompletedProcess:
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, check=False)
    if check and proc.returncode != 0:
        fail(f"{' '.join(cmd)} failed:", proc.stdout + proc.stderr)
    return proc


def start_cluster(work: Path) -> None:
    """munged, slurmctld and slurmd with every file in `work`."""
    for sub in ("state", "spool"):
        (work / sub).mkdir()
    Path("/run/munge").mkdir(parents=True, exist_ok=True)  # munged's socket: where slurmd looks
    key = work / "munge.key"
    key.write_bytes(os.urandom(1024))
    key.chmod(0o400)
    run(
        "munged", "--force", f"--key-file={key}",
        f"--pid-file={work}/munged.pid", f"--log-file={work}/munged.log",
        f"--seed-file={work}/munged.seed",
    )  # fmt: skip
    mem_mb = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") // 2**20 - 1024
    conf = SLURM_CONF.format(
        host=socket.gethostname().split(".")[0], dir=work, cpus=os.cpu_count(), mem_mb=mem_mb
    )
    (work / "slurm.conf").write_text(conf)
    os.environ["SLURM_CONF"] = str(work / "slurm.conf")
    run("slurmctld")
    conf_server = socket.gethostname().split(".")[0]
    run("slurmd", "--conf-server", conf_server)
    for _ in range(100):
        if run("sinfo", "-h", "-o", "%T", check=False).stdout.strip() == "idle":
            return
        time.sleep(0.2)
    fail("the node did not become idle:", (work / "slurmctld.log").read_text())


def stop_cluster(work: Path) -> None:
    subprocess.run(["scontrol", "shutdown"], capture_output=True, check=False)
    subprocess.run(["munged", "--stop"], capture_output=True, check=False)
    for pid_file in ("slurmctld.pid", "slurmd.pid"):  # shutdown may leave one behind
        path = work / pid_file
        if path.exists():
            subprocess.run(["kill", path.read_text().strip()], capture_output=True, check=False)
    conf = Path("/run/slurm/conf")  # slurmd's link to its cache of the configuration
    if conf.is_symlink() and Path(os.readlink(conf)).is_relative_to(work):
        conf.unlink()


def copy_sources(dest: Path) -> Path:
    for name in SOURCES:
        shutil.copytree(ROOT / name, dest / name, ignore=shutil.ignore_patterns("__pycache__"))
    return dest


def snakemake(workdir: Path, *args: str) -> subprocess.Popen:
    env = os.environ | {"PYTHONPATH": str(workdir / "src")}
    return subprocess.Popen(
        [SNAKEMAKE, *args], cwd=workdir, env=env, text=True,
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
    )  # fmt: skip


def finish(proc: subprocess.Popen, what: str, expect_ok: bool = True) -> str:
    log, _ = proc.communicate(timeout=600)
    if expect_ok and proc.returncode != 0:
        fail(f"{what} failed:", log)
    return log


def job_ids(log: str) -> list[str]:
    return re.findall(r"submitted with SLURM jobid (\d+)", log)


def outputs(workdir: Path) -> list[str]:
    return sorted(
        str(p.relative_to(workdir))
        for out in OUTPUTS
        for p in (workdir / out).rglob("*")
        if p.is_file()
    )


def same_bytes(local: Path, cluster: Path) -> int:
    names = outputs(local)
    if names != outputs(cluster):
        fail(f"other files: {sorted(set(names) ^ set(outputs(cluster)))}")
    differ = [n for n in names if not filecmp.cmp(local / n, cluster / n, shallow=False)]
    if differ:
        fail(f"the cluster's build differs from the local one: {differ}")
    return len(names)


def fail(text: str, log: str = "") -> None:
    sys.exit(f"cluster-test: {text}" + (f"\n{log[-3000:]}" if log else ""))


def check_completed(log: str) -> list[str]:
    """The job ids of `log`, each read back from SLURM as COMPLETED."""
    ids = sorted(job_ids(log), key=int)
    show = {i: run("scontrol", "show", "job", "-o", i).stdout for i in ids}
    states = {i: re.search(r"JobState=(\S+)", text)[1] for i, text in show.items()}
    if not ids or set(states.values()) != {"COMPLETED"}:
        fail(f"SLURM job states {states}", log)
    return ids


def check_batches(log: str) -> int:
    """The jobs of rule campaign_fit in `log`: one per batch of the default table."""
    from turntable.campaign import batches, read_table
    from turntable.config import validate

    config: dict = {}
    validate(config, ROOT / "workflow" / "schemas" / "config.schema.yaml")
    films, _ = read_table(ROOT / config["campaign"]["table"], results=str(ROOT / "results"))
    expected = len(batches([f.name for f in films], config["campaign"]["batch_size"]))
    found = len(re.findall(r"^rule campaign_fit:", log, re.MULTILINE))
    if found != expected or expected >= len(films):
        fail(f"{found} jobs of campaign_fit for {len(films)} films, not {expected}", log)
    return found


def cancel_one_job(cluster: Path) -> None:
    """Remove one output, cancel the job that rebuilds it; then build it again."""
    lost = sorted((cluster / "results" / "study").glob("k_*.json"))[0]
    lost.unlink()
    again = [str(lost.relative_to(cluster)), *TARGETS]  # (a missing input alone reruns nothing)
    build = snakemake(cluster, *again, *SLURM_FLAGS)
    victim = None
    for _ in range(600):
        running = run("squeue", "-h", "-t", "RUNNING", "-o", "%i", check=False).stdout.split()
        if running:
            victim = running[0]
            run("scancel", victim)
            break
        time.sleep(0.1)
    log = finish(build, "the interrupted build", expect_ok=False)
    if victim is None or build.returncode == 0 or f"SLURM-job '{victim}' failed" not in log:
        fail(f"job {victim} cancelled, but Snakemake did not report it", log)
    say(f"{lost.name} removed, its job {victim} cancelled: Snakemake reports it failed")
    log = finish(snakemake(cluster, *again, *SLURM_FLAGS), "the second run")
    say(f"second run: jobs {', '.join(check_completed(log))} COMPLETED")


def main() -> None:
    signal.signal(signal.SIGTERM, lambda *_: fail("terminated"))  # and still clean up
    parser = argparse.ArgumentParser(description=__doc__.partition("\n")[0])
    parser.add_argument(
        "--keep", type=Path, help="work in DIR and keep it (default: a temporary one)"
    )
    args = parser.parse_args()
    for tool in ("munged", "slurmctld", "slurmd", "sbatch", "squeue", "scancel"):
        if shutil.which(tool) is None:
            fail(f"{tool} not found: install slurm-wlm and munge (make cluster-test)")
    work = Path(args.keep or tempfile.mkdtemp(prefix="turntable-slurm-"))
    (work / "slurm").mkdir(parents=True)
    try:
        start_cluster(work / "slurm")
        say(f"one-node cluster up, {os.cpu_count()} CPUs: SLURM_CONF={os.environ['SLURM_CONF']}")
        local = copy_sources(work / "local")
        cluster = copy_sources(work / "cluster")
        build = snakemake(cluster, *TARGETS, *SLURM_FLAGS)
        finish(snakemake(local, *TARGETS, "--cores", str(os.cpu_count())), "the local build")
        log = finish(build, "the build through profiles/slurm")
        ids = check_completed(log)
        say(f"{len(ids)} jobs through sbatch, COMPLETED in SLURM: ids {', '.join(ids)}")
        say(f"the campaign's films fitted in {check_batches(log)} batch jobs")
        say(f"outputs byte-identical to a local build: {same_bytes(local, cluster)} files")
        cancel_one_job(cluster)
        say(f"outputs byte-identical again: {same_bytes(local, cluster)} files")
    finally:
        stop_cluster(work / "slurm")
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
    say("daemons stopped" + (f"; files kept in {work}" if args.keep else ", files removed"))


if __name__ == "__main__":
    main()
