"""config/converged.yaml end to end on reduced cells (tests/converged_reduced.yaml over the tiny matrix),
beside the tiny run of the paper's configuration: the claims in four columns with their bands and verdicts,
the overlaid figures with the other run's curves dashed and the closed cell's dotted, the texture analyser's
study; the rate and drainage bounds as their own target (converged_bounds), with a drained cell that loses
water while a sealed one does not. Slow: a few minutes on 2 cores."""
import shutil

import pandas as pd
import pytest

from analysis import columns, matrix
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


def test_the_report_judges_every_claim_in_four_columns_with_bands_and_plain_words(converged_run, tiny_run):
    out, _ = converged_run
    page = (out / "report" / "index.html").read_text()
    assert "The claims judged 4 ways" in page and str(tiny_run) in page
    assert "This run: the <b>converged SPH" in page
    for label in ("paper&#x27;s configuration (LJ, level 1)", "converged SPH (pressure coupling, h0/dx 1.2, level 2, 1 ns, 1 m/s)",
                  "closed cell, quasi-static, K 20 MPa", "closed cell, quasi-static, water&#x27;s K 2.2 GPa"):
        assert f"<th colspan='2'>{label}" in page, label
    assert "In plain words" in page and "not judged: no rate in the quasi-static scheme" in page
    ours, theirs = (pd.read_csv(d / "tables" / "claims.csv") for d in (out, tiny_run))
    assert list(ours["claim"]) == list(theirs["claim"])
    columns = pd.read_csv(out / "tables" / "claim_columns.csv")
    assert sorted(columns["column"].unique()) == ["closed_cell_K20", "closed_cell_water", "converged_sph"]
    fresh_stiffer = columns[columns["claim"].str.startswith("The plate force is largest")]
    # The reduced run has no dried case at X/X0 = 0.1: not run in every column.
    assert set(fresh_stiffer["column_verdict"]) == {"not run"}
    swell = columns[columns["claim"].str.startswith("During drying")].set_index("column")
    assert swell.loc["converged_sph", "band_changes"] == "level 2 to 3 (0.75 ns); 1 against 0.5 ns"
    assert (swell["value"] > 1).all()  # every column's fresh cell inflates at rest
    assert swell.loc["converged_sph", "band_low"] <= swell.loc["converged_sph", "value"] <= swell.loc["converged_sph", "band_high"]
    assert "For a texture analyser: slow and drained" in page
    assert (out / "tables" / "provenance.json").exists()


def test_the_named_figures_draw_the_other_runs_curves_dashed_and_the_closed_cells_dotted(root, converged_run):
    out, compare = converged_run
    config = workflow_config(root, CONVERGED + [str(compare)], out)
    for fig in ("fig07", "fig15"):
        figure = render.draw(config, fig, render.files_under(config, fig, str(out)), str(root))
        cases = matrix.figure_cases(config, fig, matrix.expand(config))
        drawn = lambda style: [ln for ax in figure.axes for ln in ax.get_lines() if ln.get_linestyle() == style  # noqa: E731
                               and len(ln.get_xdata()) and ln.get_color() != "black"]  # the apple references are black
        assert len(drawn("--")) == len(cases), fig
        closed = [n for n in cases if columns.counterpart_name(config, matrix.expand(config), matrix.expand(config)[n],
                                                               {"fluid": "closed_cell"})]
        assert len(drawn(":")) == len(closed) >= 1, fig
    figure = render.draw(config, "fig11", render.files_under(config, "fig11", str(out)), str(root))  # not named: no overlay
    assert not [ln for ax in figure.axes for ln in ax.get_lines() if ln.get_linestyle() == "--" and
                ln.get_color() != "black"]


def test_the_bounds_are_their_own_target_and_a_drained_cell_loses_water(root, converged_run):
    out, compare = converged_run
    run_workflow(root, out, CONVERGED + [str(compare)], "converged_bounds")
    page = (out / "report" / "converged_bounds.html").read_text()
    for heading in ("Rate and drainage bounds", "Toward the quasi-static limit (study rate_bounds)",
                    "Drained compression (study drainage)", "Which curve to compare with a texture analyser",
                    "Their slow end: the closed cell, quasi-static"):
        assert heading in page
    summary = pd.read_csv(out / "tables" / "converged_bounds" / "summary.csv")
    lp = summary["compression.Lp_m_per_s_Pa"]
    sph = summary["fluid"] == "sph"
    drained, sealed = summary[sph & (lp == 1e-6)].iloc[0], summary[sph & (lp == 1e-12) & (summary["dryness"] == 1.0)]
    assert drained["mass_lost_at_0.05"] > 1e-3                     # water left while the plates pressed
    assert (sealed["mass_lost_at_0.05"].abs() < 1e-4).all()         # the sealed cell keeps it
    assert drained["smoothed_stress_kPa_at_0.05"] < sealed["smoothed_stress_kPa_at_0.05"].min()
    assert (out / "figures" / "rate01.png").exists() and (out / "figures" / "drain01.png").exists()
    slow = summary[summary["compression.plate_speed_m_s"] == 0.5]
    assert (slow["strain_reached"] > 0.095).all()  # the 0.5 m/s plate gets its travel (records every 200 steps)
    quasi_static = summary[summary["fluid"] == "closed_cell"].set_index("compression.Lp_m_per_s_Pa")
    assert quasi_static.loc[1e-6, "smoothed_stress_kPa_at_0.05"] < quasi_static.loc[1e-12, "smoothed_stress_kPa_at_0.05"]


def test_a_comparison_made_by_other_code_says_so_on_the_page(root, converged_run, tiny_run, tmp_path):
    """The other run's tables/provenance.json names another commit: the page says which, and the figures'
    dashed legend entry names it."""
    out, compare = converged_run
    stale = tmp_path / "stale"
    shutil.copytree(tiny_run, stale)
    (stale / "tables" / "provenance.json").write_text('{"version": "0.1.0", "commit": "0123456789ab"}\n')
    other = tmp_path / "compare_with_stale.yaml"
    other.write_text(f"compare_with: {{output_dir: '{stale}'}}\n")
    config = workflow_config(root, CONVERGED + [str(other)], out)
    from analysis import comparison
    note = comparison.made_by_note(config)
    assert "was made by cellsim 0.1.0, commit 0123456789ab" in note and str(stale) in note
    figure = render.draw(config, "fig07", render.files_under(config, "fig07", str(out)), str(root))
    labels = [t.get_text() for t in figure.axes[-1].get_legend().get_texts()]
    assert any("(made by commit 0123456789ab)" in label for label in labels), labels
    (stale / "tables" / "provenance.json").unlink()
    assert "has no record of the code that made it" in comparison.made_by_note(config)
