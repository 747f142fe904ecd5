"""config/converged.yaml end to end on reduced cells (tests/converged_reduced.yaml over the tiny matrix),
beside the tiny run of the paper's configuration: the claims of both runs side by side, the overlaid
figures with the other run's curves dashed, the rate and drainage bounds in the report, and a drained
cell that loses water while a closed one does not. Slow: a few minutes on 2 cores."""
import pandas as pd
import pytest

from analysis import matrix
from analysis.figures import render
from conftest import CI, run_workflow, workflow_config

pytestmark = pytest.mark.slow
CONVERGED = CI + ["config/converged.yaml", "tests/tiny_matrix.yaml", "tests/converged_reduced.yaml"]


@pytest.fixture(scope="module")
def converged_run(root, tiny_run, tmp_path_factory):
    """The reduced converged run, compared with the tiny run of the paper's configuration."""
    out = tmp_path_factory.mktemp("converged results")
    compare = out.parent / "compare_with_tiny.yaml"
    compare.write_text(f"compare_with: {{output_dir: '{tiny_run}'}}\n")
    return run_workflow(root, out, CONVERGED + [str(compare)]), compare


def test_the_report_sets_the_claims_of_both_runs_side_by_side(converged_run, tiny_run):
    out, _ = converged_run
    page = (out / "report" / "index.html").read_text()
    assert "The claims under both configurations" in page and str(tiny_run) in page
    assert "This run: the <b>converged configuration" in page
    assert "paper&#x27;s configuration (LJ, level 1): value" in page
    assert "converged configuration (pressure coupling, h0/dx 1.2, level 2): value" in page
    ours, theirs = (pd.read_csv(d / "tables" / "claims.csv") for d in (out, tiny_run))
    assert list(ours["claim"]) == list(theirs["claim"])
    judged = lambda v: v.isin(["agree", "disagree"])  # noqa: E731
    both = int((judged(ours["verdict"]) & judged(theirs["verdict"])).sum())
    changed = int((judged(ours["verdict"]) & judged(theirs["verdict"]) & (ours["verdict"] != theirs["verdict"])).sum())
    assert both >= 4
    assert f"are judged in both runs; {changed} changed verdict." in page


def test_the_named_figures_draw_the_other_runs_curves_dashed(root, converged_run):
    out, compare = converged_run
    config = workflow_config(root, CONVERGED + [str(compare)], out)
    for fig in ("fig07", "fig15"):
        figure = render.draw(config, fig, str(out), str(root))
        cases = matrix.figure_cases(config, fig, matrix.expand(config))
        dashed = [ln for ax in figure.axes for ln in ax.get_lines() if ln.get_linestyle() == "--" and
                  len(ln.get_xdata()) and ln.get_color() != "black"]  # the apple references are black
        assert len(dashed) == len(cases), fig
    figure = render.draw(config, "fig11", str(out), str(root))  # not named: no overlay
    assert not [ln for ax in figure.axes for ln in ax.get_lines() if ln.get_linestyle() == "--" and
                ln.get_color() != "black"]


def test_the_bounds_are_in_the_report_and_a_drained_cell_loses_water(converged_run):
    out, _ = converged_run
    page = (out / "report" / "index.html").read_text()
    for heading in ("Rate and drainage bounds", "Toward the quasi-static limit (study rate_bounds)",
                    "Drained compression (study drainage)", "Which curve to compare with a texture analyser"):
        assert heading in page
    summary = pd.read_csv(out / "tables" / "summary.csv")
    lp = summary["compression.Lp_m_per_s_Pa"]
    drained, closed = summary[lp == 1e-6].iloc[0], summary[(lp == 1e-12) & (summary["dryness"] == 1.0)]
    assert drained["mass_lost_at_0.05"] > 1e-3                     # water left while the plates pressed
    assert (closed["mass_lost_at_0.05"].abs() < 1e-4).all()         # the closed cell keeps it
    assert drained["smoothed_stress_kPa_at_0.05"] < closed["smoothed_stress_kPa_at_0.05"].min()
    assert (out / "figures" / "rate01.png").exists() and (out / "figures" / "drain01.png").exists()
    slow = summary[summary["compression.plate_speed_m_s"] == 0.5]
    assert (slow["strain_reached"] > 0.095).all()  # the 0.5 m/s plate gets its travel (records every 200 steps)
