"""The workflow on a cluster: a one-node SLURM on localhost (started here, in a temporary directory,
and stopped again by process id) runs the tiny matrix (tests/tiny_matrix.yaml: every rule, 5 cases)
through workflow/profiles/slurm. Every result, table, figure and page is byte for byte the one of the
same study run locally, and the jobs really went through SLURM: each submission left its SLURM output
file and the controller logged its completion. Skipped, saying why, only where SLURM cannot run."""
import re
import subprocess

import pytest

from conftest import TINY, assert_same_results, workflow_options
from slurm_cluster import OneNodeSlurm, available

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    reason = available()
    if reason:
        pytest.skip(f"one-node SLURM unavailable: {reason}")
    slurm = OneNodeSlurm(tmp_path_factory.mktemp("slurm"))
    with slurm:
        yield slurm


def test_tiny_study_runs_through_slurm_with_the_local_results(root, tmp_path, cluster, tiny_run):
    out, logs = tmp_path / "results", tmp_path / "slurm-logs"
    env = dict(cluster.env, CELLSIM_SLURM_LOGS=str(logs))
    command = ["snakemake", "--profile", "workflow/profiles/slurm", *workflow_options(out, TINY), "--nolock"]
    done = subprocess.run(command, cwd=root, env=env, capture_output=True, text=True, timeout=2400)
    assert done.returncode == 0, (done.stdout + done.stderr)[-4000:] + cluster.logs()
    assert_same_results(out, tiny_run)

    submitted = sorted(logs.glob("*.out"))
    rests = len(list(out.glob("runs/rest/*.h5")))
    dryings = len(list(out.glob("runs/dried/*.h5")))
    compressions = len(list(out.glob("runs/*.h5")))
    assert compressions == 5 and dryings == 4 and rests == 3
    # Every settle and drying is its own job; compressions go in groups of up to 8 (more groups when
    # their dried states are ready at different times), so fewer jobs than one per compression.
    assert rests + dryings + 1 <= len(submitted) < rests + dryings + compressions, [p.name for p in submitted]
    controller_log = (cluster.dir / "log" / "slurmctld.log").read_text()
    completed = set(re.findall(r"_job_complete: JobId=(\d+) done", controller_log))
    ids = {re.search(r"-(\d+)\.out$", p.name).group(1) for p in submitted}
    assert ids <= completed, f"jobs with output but not completed by SLURM: {sorted(ids - completed)}"
