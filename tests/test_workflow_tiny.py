"""The pipeline end to end on the tiny matrix (tests/tiny_matrix.yaml: every study of the default target
with a case or two of the reduced cell, so that every rule runs and all 18 figures are drawn; about a
minute on 2 cores): every figure shows its data, the tables hold every case and parameter, the report
shows every figure and judges or names every claim. The same run is the reference the resumed run and
the run through SLURM must equal (test_workflow_resume.py, test_slurm.py). The CI study's own checks
(48 cases, the claims it can judge) are in test_workflow_ci.py, in the slow tier."""
import subprocess
import sys

import numpy as np
import pandas as pd

from analysis import matrix
from conftest import TINY, workflow_config
from default_target_checks import check_default_figures, check_tables, report_claims


def test_every_figure_shows_its_data(root, tiny_run, tmp_path):
    check_default_figures(root, TINY, tiny_run, tmp_path)


def test_tables_hold_every_case_and_parameter(root, tiny_run):
    config = workflow_config(root, TINY, tiny_run)
    cases = matrix.target_cases(config, matrix.expand(config))
    assert len(cases) >= 5
    summary = check_tables(tiny_run, cases)
    for column in ["drying_energy_residual_over_flow", "compression_energy_residual_over_work"]:
        assert column in summary.columns, column


def test_report_shows_every_figure_and_every_claim(tiny_run):
    claims = report_claims(tiny_run)
    # The tiny matrix leaves out most cases a claim compares: those claims say so ('not run'); the rest are judged.
    assert set(claims["verdict"]) <= {"agree", "disagree", "not run", "not reached"}
    assert claims["verdict"].isin(["agree", "disagree"]).any()


def test_the_reading_example_reads_a_case(root, tiny_run, tmp_path):
    """docs/examples/read_results.py, as output-reference.md tells a reader to run it: it names the case's
    stress at strain 0.05 from the summary, reads the same curve from the HDF5 file (its value there,
    interpolated as the summary's, agrees) and draws it."""
    summary = pd.read_csv(f"{tiny_run}/tables/summary.csv").set_index("case")
    case = summary["stress_kPa_at_0.05"].dropna().index[-1]
    curve = tmp_path / "curve.png"
    done = subprocess.run([sys.executable, root / "docs/examples/read_results.py", tiny_run, case, "-o", curve],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert f"stress at strain 0.05 = {summary.loc[case, 'stress_kPa_at_0.05']:.1f} kPa" in done.stdout
    assert "completed = 1" in done.stdout
    assert curve.stat().st_size > 10_000

    sys.path.insert(0, str(root / "docs/examples"))
    from read_results import read_curve
    strain, stress_kPa, _ = read_curve(f"{tiny_run}/runs/{case}.h5")
    at = np.interp(0.05, strain.to_numpy(), stress_kPa.to_numpy())  # strain rises through the compression
    assert np.isclose(at, summary.loc[case, "stress_kPa_at_0.05"], rtol=1e-6)

    missing = subprocess.run([sys.executable, root / "docs/examples/read_results.py", tiny_run, "no_such_case"],
                             capture_output=True, text=True, timeout=120)
    assert missing.returncode != 0 and "no case 'no_such_case'" in missing.stderr
