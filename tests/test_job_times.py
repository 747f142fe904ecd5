"""A target's job times from its logs (analysis/job_times.py): the core time of each kind of job and the
longest chain of one case's settle, drying and compression, the time a cluster takes."""
import pytest

from analysis import job_times
from conftest import workflow_config


def test_job_times_sum_the_logs_and_find_the_longest_chain(root, tmp_path):
    config = workflow_config(root, ["config/ci.yaml"], tmp_path)
    _, cases = job_times.times(config)
    slow = cases[3]
    for kind in job_times.KINDS:
        (tmp_path / "logs" / kind).mkdir(parents=True)
    for case in cases:
        # A settle's log reports the settle's time and its steps' (0 s); a drying's and a compression's, their steps'.
        (tmp_path / "logs" / "settle" / f"{case.rest}.log").write_text(
            "cellsim: settle: 400 pseudo-steps to rest at 200.0 kPa, residual 0.0003, fluid mass x 1.0138, 2.5 s wall time\n"
            "cellsim: done, 0 steps, t = 0.00 us, 0.0 s wall time (0.000 ms/step)\n")
        (tmp_path / "logs" / "dry" / f"{case.dried}.log").write_text(
            "cellsim: done, 5000 steps, t = 5.00 us, 10.0 s wall time (2 ms/step)\n")
        seconds = 100.0 if case is slow else 5.0
        (tmp_path / "logs" / "compress" / f"{case.name}.log").write_text(
            f"cellsim: done, 25000 steps, t = 30.00 us, {seconds} s wall time (0.5 ms/step)\n")
    total, name, parts = job_times.longest_chain(config)
    assert name == slow.name and parts == (2.5, 10.0, 100.0) and total == pytest.approx(112.5)
    lines = job_times.report(config)
    assert lines[2] == f"compress: {len(cases)} jobs, {(5.0 * (len(cases) - 1) + 100.0) / 60:.1f} core-min"
    assert lines[-1].startswith(f"longest chain: 1.9 min, {slow.name} (settle 2 s, drying 10 s, compression 100 s)")
    (tmp_path / "logs" / "compress" / f"{slow.name}.log").unlink()  # not run yet: counted, not timed
    assert job_times.longest_chain(config)[1] != slow.name
    assert "(1 without a log)" in job_times.report(config)[2]
