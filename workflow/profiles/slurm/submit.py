#!/usr/bin/python3
"""Snakemake --cluster command: submits one job script with sbatch and prints the SLURM job id.

Cores, memory and time come from the job's threads and resources (config/config.yaml `resources`);
partition, account and extra options from site.yaml beside this file. SLURM's own output for each
job goes to $CELLSIM_SLURM_LOGS (default slurm-logs/) as <rule or group>-<slurm job id>.out."""
import os
import pathlib
import shlex
import subprocess
import sys

import yaml
from snakemake.utils import read_job_properties

HERE = pathlib.Path(__file__).parent


def main(jobscript):
    job = read_job_properties(jobscript)
    site = yaml.safe_load((HERE / "site.yaml").read_text()) or {}
    resources = job.get("resources", {})
    name = job.get("groupid", job.get("rule", "job"))
    log_dir = pathlib.Path(os.environ.get("CELLSIM_SLURM_LOGS", "slurm-logs"))
    log_dir.mkdir(parents=True, exist_ok=True)
    args = ["sbatch", "--parsable", f"--job-name=cellsim-{name}", f"--cpus-per-task={job.get('threads', 1)}",
            f"--output={log_dir}/{name}-%j.out"]
    if "mem_mb" in resources:
        args.append(f"--mem={resources['mem_mb']}")
    if "runtime" in resources:
        args.append(f"--time={resources['runtime']}")
    for key in ("partition", "account"):
        if site.get(key):
            args.append(f"--{key}={site[key]}")
    args += shlex.split(site.get("extra") or "")
    done = subprocess.run(args + [jobscript], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"sbatch failed ({done.returncode}): {done.stderr.strip()}")
    print(done.stdout.strip().split(";")[0])  # the job id (";cluster" is appended on federations)


if __name__ == "__main__":
    main(sys.argv[-1])
