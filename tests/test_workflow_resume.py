"""A killed workflow resumes as the README says: kill snakemake and its jobs mid-run (SIGKILL to the
process group, as a power cut would), run the README's recovery commands, and it finishes, reruns only
what was unfinished, and every result, table and figure equals the uninterrupted run's, byte for byte. A
result file never exists under its final name unless it is complete. On the tiny matrix
(tests/tiny_matrix.yaml: every rule, 5 cases). Slow: about two minutes."""
import os
import pathlib
import re
import shlex
import signal
import subprocess
import time

import h5py
import pytest

from conftest import TINY, assert_same_results, between_markers, workflow_command, workflow_options

pytestmark = pytest.mark.slow


def reported_finished(log_text):
    """Outputs of the jobs the workflow's log reports finished ('Finished job N.'): Snakemake records a
    job as complete before it says so, and keeps exactly these after a kill. (A result file can be
    whole on disk a moment before that; such a job was not finished, and a rerun may redo it.)"""
    outputs, done, current = {}, set(), []
    for line in log_text.splitlines():
        line = line.strip()
        if line.startswith("output: "):
            current = [path.strip() for path in line[len("output: "):].split(",")]
        elif line.startswith("jobid: "):
            outputs[int(line.split()[1])] = current
        elif re.fullmatch(r"Finished job \d+\.", line):
            done.add(int(line.split()[2].rstrip(".")))
    return {pathlib.Path(path) for job in done for path in outputs.get(job, [])}


def finished_runs(out):
    """Result files whose job had finished: the HDF5 file and both XDMF sidecars are there."""
    done = {}
    for h5 in [*out.glob("runs/*.h5"), *out.glob("runs/dried/*.h5"), *out.glob("runs/rest/*.h5")]:
        stem = str(h5)[:-3]
        if os.path.exists(stem + ".wall.xdmf") and os.path.exists(stem + ".fluid.xdmf"):
            done[h5.relative_to(out)] = h5.stat().st_mtime_ns
    return done


def readme_recovery(root):
    """The commands of the README's recovery block, comments stripped."""
    text = (root / "README.md").read_text()
    block = between_markers(text, "recovery")
    return [shlex.split(line.split("#", 1)[0]) for line in block.splitlines() if line.startswith("snakemake")]


def test_killed_workflow_resumes_as_the_readme_says(root, tmp_path, tiny_run):
    out = tmp_path / "results"
    command = workflow_command(out, TINY)  # the interrupted run's command, with its lock, as a user runs it
    options = workflow_options(out, TINY)
    log = tmp_path / "interrupted.log"
    with open(log, "w") as stderr:
        job = subprocess.Popen(command, cwd=root, stdout=subprocess.DEVNULL, stderr=stderr, start_new_session=True)
        deadline = time.time() + 900
        while time.time() < deadline and len(list(out.glob("runs/*.h5"))) < 2:  # some compressions done
            assert job.poll() is None, "the workflow ended before it could be interrupted"
            time.sleep(0.2)
        os.killpg(job.pid, signal.SIGKILL)  # snakemake and the solver jobs, as a power cut would
        job.wait()

    reported = reported_finished(log.read_text())
    before = {path: mtime for path, mtime in finished_runs(out).items() if out / path in reported}
    assert before, "nothing had finished when the workflow was killed"
    for h5 in [*out.glob("runs/*.h5"), *out.glob("runs/dried/*.h5"), *out.glob("runs/rest/*.h5")]:
        with h5py.File(h5) as f:  # under its final name only when complete
            assert f.attrs["completed"] == 1, h5

    # Without the README's first step the rerun stops at the dead run's lock: the reason for that step.
    # (A dry run takes no lock, so this is the real command; it stops before running any job.)
    locked = subprocess.run(["snakemake", "--cores", "2", *options, "--rerun-incomplete"], cwd=root,
                            capture_output=True, text=True, timeout=600)
    assert locked.returncode != 0 and "cannot be locked" in locked.stdout + locked.stderr
    commands = readme_recovery(root)
    assert [c[:2] for c in commands] == [["snakemake", "--unlock"], ["snakemake", "--cores"]], commands
    for command in commands:
        done = subprocess.run(command + options, cwd=root, capture_output=True, text=True, timeout=1800)
        assert done.returncode == 0, f"{command}: " + (done.stdout + done.stderr)[-4000:]

    after = finished_runs(out)
    for path, mtime in before.items():
        assert after[path] == mtime, f"{path} finished before the kill but was run again"
    assert set(before) < set(after), "the kill left nothing unfinished: the recovery was not tested"
    assert set(after) == set(finished_runs(tiny_run))
    assert not list(out.glob("runs/**/*.partial")), "stale partial files left behind"
    assert_same_results(out, tiny_run)

