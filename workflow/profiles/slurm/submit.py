"""Snakemake --cluster command: submits one job script with sbatch and prints the SLURM job id.

Cores, memory and time come from the job's threads and resources (config/config.yaml `resources`),
capped at the largest node's CPUs and memory (a group of jobs asks for their sum and would otherwise
never start on small nodes; Snakemake then runs the group's jobs within what was granted); partition,
account and extra options from site.yaml beside this file. SLURM's own output for each
job goes to $CELLSIM_SLURM_LOGS (default slurm-logs/) as <rule or group>-<slurm job id>.out."""
import os
import pathlib
import shlex
import subprocess
import sys

import yaml
from snakemake.utils import read_job_properties

HERE = pathlib.Path(__file__).parent


def largest_node(partition):
    """(CPUs, memory MB) of the partition's largest node, from sinfo; (None, None) if unknown."""
    cmd = ["sinfo", "-h", "-o", "%c %m"] + ([f"--partition={partition}"] if partition else [])
    done = subprocess.run(cmd, capture_output=True, text=True)
    sizes = [tuple(int(v.rstrip("+")) for v in line.split()) for line in done.stdout.splitlines()
             if done.returncode == 0 and len(line.split()) == 2]
    return (max(c for c, _ in sizes), max(m for _, m in sizes)) if sizes else (None, None)


def main(jobscript):
    job = read_job_properties(jobscript)
    site = yaml.safe_load((HERE / "site.yaml").read_text()) or {}
    resources = job.get("resources", {})
    name = job.get("groupid", job.get("rule", "job"))
    log_dir = pathlib.Path(os.environ.get("CELLSIM_SLURM_LOGS", "slurm-logs"))
    log_dir.mkdir(parents=True, exist_ok=True)
    max_cpus, max_mem = largest_node(site.get("partition"))
    cpus = int(job.get("threads", resources.get("_cores", 1)))
    cpus = min(cpus, max_cpus) if max_cpus else cpus
    args = ["sbatch", "--parsable", f"--job-name=cellsim-{name}", f"--cpus-per-task={cpus}",
            f"--output={log_dir}/{name}-%j.out"]
    if "mem_mb" in resources:
        mem = int(resources["mem_mb"])
        args.append(f"--mem={min(mem, max_mem) if max_mem else mem}")
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
