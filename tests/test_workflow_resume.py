"""A killed workflow resumes: kill snakemake (and its jobs) mid-run, run it again, and it finishes,
reruns only what was unfinished, and every result equals the uninterrupted run's, byte for byte.
A result file never exists under its final name unless it is complete. Slow: a CI run and a half."""
import os
import signal
import subprocess
import time

import h5py
import pytest

from conftest import run_ci_workflow

pytestmark = pytest.mark.slow


def finished_runs(out):
    """Result files whose job had finished: the HDF5 file and both XDMF sidecars are there."""
    done = {}
    for h5 in list(out.glob("runs/*.h5")) + list(out.glob("runs/dried/*.h5")):
        stem = str(h5)[:-3]
        if os.path.exists(stem + ".wall.xdmf") and os.path.exists(stem + ".fluid.xdmf"):
            done[h5.relative_to(out)] = h5.stat().st_mtime_ns
    return done


def test_killed_workflow_resumes_and_matches_uninterrupted_run(root, tmp_path, ci_run):
    out = tmp_path / "results"
    job = subprocess.Popen(["snakemake", "--nolock", "--cores", "2", "--configfile", "config/ci.yaml", "--config",
                            f"output_dir={out}", "-q"], cwd=root, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.time() + 900
    while time.time() < deadline and len(list(out.glob("runs/*.h5"))) < 4:  # some compressions done
        assert job.poll() is None, "the workflow ended before it could be interrupted"
        time.sleep(0.5)
    os.killpg(job.pid, signal.SIGKILL)  # snakemake and the solver jobs, as a power cut would
    job.wait()

    before = finished_runs(out)
    assert before, "nothing had finished when the workflow was killed"
    for h5 in list(out.glob("runs/*.h5")) + list(out.glob("runs/dried/*.h5")):
        with h5py.File(h5) as f:  # under its final name only when complete
            assert f.attrs["completed"] == 1, h5

    done = run_ci_workflow(root, out, "--rerun-incomplete")
    assert done.returncode == 0, (done.stdout + done.stderr)[-4000:]

    after = finished_runs(out)
    for path, mtime in before.items():
        assert after[path] == mtime, f"{path} finished before the kill but was run again"
    reference = finished_runs(ci_run)
    assert set(after) == set(reference)
    for path in reference:
        assert (out / path).read_bytes() == (ci_run / path).read_bytes(), f"{path} differs from the uninterrupted run"
    assert not list(out.glob("runs/**/*.partial")), "stale partial files left behind"
    assert (out / "report" / "index.html").is_file()
