"""The whole pipeline end to end on config/ci.yaml (the paper's 48 cases on reduced cells): every case
runs, every figure shows its data (tests/figure_checks.py), the tables and the report are written, every
claim is judged. Slow: about 12 minutes on 2 cores (scripts/test --all); scripts/test runs the same checks
on the tiny matrix (test_workflow_tiny.py)."""
import subprocess
import textwrap

import pytest

from analysis import matrix
from conftest import CI, between_markers, job_counts, workflow_command, workflow_config
from default_target_checks import check_default_figures, check_tables, report_claims

pytestmark = pytest.mark.slow


def test_every_figure_shows_its_data(root, ci_run, tmp_path):
    check_default_figures(root, CI, ci_run, tmp_path)


def test_tables_hold_every_case_and_parameter(root, ci_run):
    config = workflow_config(root, CI, ci_run)
    cases = matrix.target_cases(config, matrix.expand(config))
    assert len(cases) == 48
    summary = check_tables(ci_run, cases)
    # Every reduced cell reaches steady state before its cap (else the report warns).
    assert summary["drying_steady"].all(), summary.loc[~summary["drying_steady"], ["case", "warning"]]


def test_report_shows_every_figure_and_the_claims(ci_run):
    claims = report_claims(ci_run)
    # The CI study runs every case a claim needs (none is "not run"); only the claim on strains above
    # 0.1 cannot be judged, as config/ci.yaml stops every compression at strain 0.1.
    not_judged = claims.loc[~claims["verdict"].isin(["agree", "disagree"])]
    assert list(not_judged["verdict"]) == ["not reached"], not_judged
    assert not_judged["claim"].iloc[0] == "X/X0 = 0.1 stays above X/X0 = 0.3 at strains above 0.1"


def documented_new_axis(root):
    """docs/extending.md's example of a study on a new axis (between its new-axis markers), as YAML."""
    block = between_markers((root / "docs" / "extending.md").read_text(), "new-axis")
    return textwrap.dedent(block.split("```yaml", 1)[1].split("```", 1)[0])


def test_adding_the_readmes_new_axis_runs_only_the_new_cases(root, ci_run, tmp_path):
    """Extending a finished study as docs/extending.md shows reruns no case that was there: the plan over the
    CI run holds the new cases' runs (kb1e-09 at X/X0 = 1 and 0.1: two compressions, two dryings, one
    settle) and the tables and report that gather them, nothing else."""
    extra = tmp_path / "new-axis.yaml"
    extra.write_text(documented_new_axis(root))
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
