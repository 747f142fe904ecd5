"""The pipeline end to end on the tiny matrix (tests/tiny_matrix.yaml: every study of the default target
with a case or two of the reduced cell, so that every rule runs and all 18 figures are drawn; about a
minute on 2 cores): every figure shows its data, the tables hold every case and parameter, the report
shows every figure and judges or names every claim. The same run is the reference the resumed run and
the run through SLURM must equal (test_workflow_resume.py, test_slurm.py). The CI study's own checks
(48 cases, the claims it can judge) are in test_workflow_ci.py, in the slow tier."""
import pandas as pd

from analysis import matrix
from conftest import TINY, workflow_config
from figure_checks import check_figures


def test_every_figure_shows_its_data(root, tiny_run, tmp_path):
    config = workflow_config(root, TINY, tiny_run)
    figures = matrix.target_figures(config)
    assert len(figures) == 18  # the paper's; the other targets' are not drawn by default
    check_figures(config, tiny_run, root, tmp_path, figures)
    assert not any(tiny_run.glob("figures/conv*")) and not any(tiny_run.glob("figures/tis*"))


def test_tables_hold_every_case_and_parameter(root, tiny_run):
    config = workflow_config(root, TINY, tiny_run)
    cases = matrix.target_cases(config, matrix.expand(config))
    summary = pd.read_csv(tiny_run / "tables" / "summary.csv")
    assert set(summary["case"]) == set(cases) and len(cases) >= 5
    for column in ["dryness", "turgor_kPa", "plate_speed_m_s", "G_MPa", "t0_um", "D_um", "cell.n_wall",
                   "drying.dryness", "stress_kPa_at_0.05", "dried_V_over_V0", "peak_force_top_uN",
                   "drying_steady", "drying_steady_time_us", "settle_iterations", "warning",
                   "drying_energy_residual_over_flow", "compression_energy_residual_over_work"]:
        assert column in summary.columns, column
    assert summary["stress_kPa_at_0.05"].notna().all()
    series = pd.read_csv(tiny_run / "tables" / "timeseries.csv", usecols=["case", "stage", "plate_stress_Pa"])
    assert set(series["case"]) == set(summary["case"])
    assert (series["stage"] == 1).any() and (series["stage"] == 0).any()
    assert set(pd.read_csv(tiny_run / "manifest.csv")["case"]) == set(summary["case"])


def test_report_shows_every_figure_and_every_claim(tiny_run):
    html = (tiny_run / "report" / "index.html").read_text()
    for k in range(1, 19):
        assert f"figures/fig{k:02d}.png" in html
    claims = pd.read_csv(tiny_run / "tables" / "claims.csv")
    assert len(claims) == 16
    # The tiny matrix leaves out most cases a claim compares: those claims say so ('not run'); the rest are judged.
    assert set(claims["verdict"]) <= {"agree", "disagree", "not run", "not reached"}
    assert claims["verdict"].isin(["agree", "disagree"]).any()
    assert "Model closures" in html and "wall-pressure closure" in html
