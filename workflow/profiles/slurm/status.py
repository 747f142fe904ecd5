"""Snakemake --cluster-status command: prints running, success or failed for a SLURM job id.

Asks scontrol first (works without SLURM accounting while the controller remembers the job), then
sacct (needs accounting). Timeouts, out-of-memory, node failures and cancellations are failures."""
import subprocess
import sys
import time

RUNNING = {"PENDING", "CONFIGURING", "RUNNING", "COMPLETING", "SUSPENDED", "REQUEUED", "RESIZING", "STAGE_OUT"}
FAILED = {"FAILED", "TIMEOUT", "OUT_OF_MEMORY", "NODE_FAIL", "CANCELLED", "PREEMPTED", "BOOT_FAIL", "DEADLINE",
          "REVOKED", "SPECIAL_EXIT"}


def state_from_scontrol(job_id):
    done = subprocess.run(["scontrol", "-o", "show", "job", job_id], capture_output=True, text=True)
    if done.returncode != 0:
        return None
    for field in done.stdout.split():
        if field.startswith("JobState="):
            return field.split("=", 1)[1]
    return None


def state_from_sacct(job_id):
    done = subprocess.run(["sacct", "-j", job_id, "-X", "-n", "-P", "-o", "State"], capture_output=True, text=True)
    if done.returncode != 0 or not done.stdout.strip():
        return None
    return done.stdout.split()[0].split("+")[0]  # "CANCELLED by 0" -> CANCELLED


def main(job_id):
    for attempt in range(5):
        state = state_from_scontrol(job_id) or state_from_sacct(job_id)
        if state:
            break
        time.sleep(2 * (attempt + 1))
    else:
        print("failed")  # SLURM no longer knows the job and there is no accounting: assume the worst
        return
    if state == "COMPLETED":
        print("success")
    elif state in FAILED:
        print("failed")
    else:
        print("running")


if __name__ == "__main__":
    main(sys.argv[1])
