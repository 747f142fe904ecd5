"""The workflow on a cluster: a one-node SLURM on localhost (started here, in a temporary directory,
and stopped again by process id) runs config/ci.yaml through workflow/profiles/slurm. Every figure
appears, and the jobs really went through SLURM: each submission left its SLURM output file and the
controller logged its completion. Skipped, saying why, only where SLURM cannot run."""
import re
import subprocess

import pytest
import yaml

from analysis import matrix

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


def test_ci_study_runs_through_slurm(root, tmp_path, cluster):
    out, logs = tmp_path / "results", tmp_path / "slurm-logs"
    env = dict(cluster.env, CELLSIM_SLURM_LOGS=str(logs))
    done = subprocess.run(["snakemake", "--profile", "workflow/profiles/slurm", "--configfile", "config/ci.yaml",
                           "--config", f"output_dir={out}", "--nolock"], cwd=root, env=env, capture_output=True,
                          text=True, timeout=2400)
    assert done.returncode == 0, (done.stdout + done.stderr)[-4000:] + cluster.logs()

    for fig in matrix.target_figures(yaml.safe_load((root / "config" / "config.yaml").read_text())):
        for ext in ("png", "pdf"):
            assert (out / "figures" / f"{fig}.{ext}").stat().st_size > 10_000, fig

    submitted = sorted(logs.glob("*.out"))
    rests = len(list(out.glob("runs/rest/*.h5")))
    dryings = len(list(out.glob("runs/dried/*.h5")))
    compressions = len(list(out.glob("runs/*.h5")))
    assert compressions == 48 and dryings == 39 and rests == 10
    # Every settle and drying is its own job; compressions go in groups of up to 8 (a few more if not
    # packed tight).
    assert rests + dryings + compressions // 8 <= len(submitted) < rests + dryings + compressions
    controller_log = (cluster.dir / "log" / "slurmctld.log").read_text()
    completed = set(re.findall(r"_job_complete: JobId=(\d+) done", controller_log))
    ids = {re.search(r"-(\d+)\.out$", p.name).group(1) for p in submitted}
    assert ids <= completed, f"jobs with output but not completed by SLURM: {sorted(ids - completed)}"
