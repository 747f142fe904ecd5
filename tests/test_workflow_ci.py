"""The whole pipeline end to end on config/ci.yaml (the paper's 48 cases on reduced cells): every case
runs, every figure shows its data (tests/figure_checks.py), the tables and the report are written, every
claim is judged. Slow: about 12 minutes on 2 cores (scripts/test --all); scripts/test runs the same checks
on the tiny matrix (test_workflow_tiny.py)."""
import subprocess
import textwrap

import pandas as pd
import pytest

from analysis import matrix
from conftest import CI, between_markers, job_counts, workflow_command, workflow_config
from figure_checks import check_figures

pytestmark = pytest.mark.slow


def test_every_figure_shows_its_data(root, ci_run, tmp_path):
    config = workflow_config(root, CI, ci_run)
    figures = matrix.target_figures(config)
    assert len(figures) == 18  # the paper's; the convergence target's are not drawn by default
    check_figures(config, ci_run, root, tmp_path, figures)
    assert not any(ci_run.glob("figures/conv*")) and not any(ci_run.glob("figures/tis*"))


def test_tables_hold_every_case_and_parameter(ci_run):
    summary = pd.read_csv(ci_run / "tables" / "summary.csv")
    assert len(summary) == 48
    for column in ["dryness", "turgor_kPa", "plate_speed_m_s", "G_MPa", "t0_um", "D_um", "cell.n_wall",
                   "drying.dryness", "stress_kPa_at_0.05", "dried_V_over_V0", "peak_force_top_uN",
                   "drying_steady", "drying_steady_time_us", "settle_iterations", "warning"]:
        assert column in summary.columns, column
    assert summary["stress_kPa_at_0.05"].notna().all()
    # Every reduced cell reaches steady state before its cap (else the report warns).
    assert summary["drying_steady"].all(), summary.loc[~summary["drying_steady"], ["case", "warning"]]
    series = pd.read_csv(ci_run / "tables" / "timeseries.csv", usecols=["case", "stage", "plate_stress_Pa"])
    assert set(series["case"]) == set(summary["case"])
    assert (series["stage"] == 1).any() and (series["stage"] == 0).any()
    manifest = pd.read_csv(ci_run / "manifest.csv")
    assert set(manifest["case"]) == set(summary["case"])


def test_report_shows_every_figure_and_the_claims(ci_run):
    html = (ci_run / "report" / "index.html").read_text()
    for k in range(1, 19):
        assert f"figures/fig{k:02d}.png" in html
    claims = pd.read_csv(ci_run / "tables" / "claims.csv")
    assert len(claims) == 16
    # The CI study runs every case a claim needs (none is "not run"); only the claim on strains above
    # 0.1 cannot be judged, as config/ci.yaml stops every compression at strain 0.1.
    not_judged = claims.loc[~claims["verdict"].isin(["agree", "disagree"])]
    assert list(not_judged["verdict"]) == ["not reached"], not_judged
    assert not_judged["claim"].iloc[0] == "X/X0 = 0.1 stays above X/X0 = 0.3 at strains above 0.1"
    assert "Model closures" in html and "wall-pressure closure" in html


def readme_new_axis(root):
    """The README's example of a study on a new axis (between its new-axis markers), as YAML."""
    block = between_markers((root / "README.md").read_text(), "new-axis")
    return textwrap.dedent(block.split("```yaml", 1)[1].split("```", 1)[0])


def test_adding_the_readmes_new_axis_runs_only_the_new_cases(root, ci_run, tmp_path):
    """Extending a finished study as the README shows reruns no case that was there: the plan over the
    CI run holds the new cases' runs (kb1e-09 at X/X0 = 1 and 0.1: two compressions, two dryings, one
    settle) and the tables and report that gather them, nothing else."""
    extra = tmp_path / "new-axis.yaml"
    extra.write_text(readme_new_axis(root))
    done = subprocess.run(workflow_command(ci_run, CI + [str(extra)], "-n", "--nolock"), cwd=root,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    counts = job_counts(done.stdout)
    runs = {rule: counts.pop(rule) for rule in ("compress", "dry", "settle")}
    assert runs == {"compress": 2, "dry": 2, "settle": 1}, runs
    planned = [line.split(":", 1)[1] for line in done.stdout.splitlines() if line.strip().startswith("output:")]
    reruns = [line for line in planned if "/runs/" in line and "kb1e-09" not in line]
    assert not reruns, f"existing cases rerun: {reruns}"
    assert set(counts) <= {"case_file", "dried_case_file", "rest_case_file", "cell_view", "aggregate", "manifest",
                           "report", "all"}, counts  # no figure: the new study has none
    assert counts["cell_view"] == 2, counts
