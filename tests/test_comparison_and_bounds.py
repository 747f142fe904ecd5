"""A run beside another (analysis/comparison.py) and the rate and drainage bounds (analysis/bounds.py), on
made-up tables whose answers are known: claims matched by text, a changed verdict said in words, the
quasi-static check between the two slowest speeds, the water a drained cell lost and the real time it
stands for, and the other run's curves dashed in an overlaid figure."""
import numpy as np
import pandas as pd
import pytest
import yaml

from analysis import bounds, comparison, matrix
from analysis.figures import curves
from conftest import workflow_config


def claim(text, value, verdict, figure=7):
    return {"claim": text, "figure": figure, "measured": "ratio", "value": value, "threshold": "> 1", "verdict": verdict}


def test_claims_are_matched_by_text_and_figure_and_a_changed_verdict_is_said_in_words():
    ours = [claim("fresh is stiffer", 1.4, "agree"), claim("G does not matter", 0.3, "disagree", 15),
            claim("turgor matters", np.nan, "not run", 10), claim("new claim", 2.0, "agree")]
    theirs = [claim("fresh is stiffer", 2.3, "agree"), claim("G does not matter", 0.05, "agree", 15),
              claim("turgor matters", 1.2, "agree", 10)]
    table = comparison.side_by_side(ours, theirs)
    assert [r["other_verdict"] for r in table] == ["agree", "agree", "agree", "not run"]
    assert [r["other_value"] for r in table[:3]] == [2.3, 0.05, 1.2]
    assert [r["changed"] for r in table] == [False, True, False, False]  # "not run" is no change
    text = comparison.changed_text(table, "paper's", "converged")
    assert "Of 4 claims, 2 are judged in both runs; 1 changed verdict." in text
    assert "G does not matter (fig 15): agree with the paper&#x27;s (ratio = 0.05), disagree with the converged (0.3" in text
    same = comparison.changed_text(comparison.side_by_side(ours[:1], theirs[:1]), "a", "b")
    assert "Every conclusion judged in both runs stands" in same


def test_without_the_other_run_the_report_says_how_to_get_it(tmp_path):
    config = {"compare_with": {"output_dir": str(tmp_path / "none"), "label": "paper's configuration", "this_run": "ours"}}
    text = comparison.section(config, [claim("fresh is stiffer", 1.4, "agree")])
    assert "has not been run" in text and "snakemake --cores 2" in text


def rate_summary(stresses):
    """A summary of the rate study: {(dryness, speed): (stress at 0.05, at 0.10)}."""
    return pd.DataFrame([{"studies": "rate_bounds", "dryness": x, bounds.SPEED: v, "smoothed_stress_kPa_at_0.05": a,
                          "smoothed_stress_kPa_at_0.10": b} for (x, v), (a, b) in stresses.items()])


def test_the_quasi_static_check_compares_the_two_slowest_speeds():
    summary = rate_summary({(1.0, 1): (120, 300), (1.0, 0.5): (110, 280), (1.0, 0.1): (102, 262.5),
                            (1.0, 0.25): (104, 250)})
    table = bounds.quasi_static_table(summary)
    assert list(table["strain"]) == [0.05, 0.10]
    assert list(table.columns[2:6]) == ["1 m/s [kPa]", "0.5 m/s [kPa]", "0.25 m/s [kPa]", "0.1 m/s [kPa]"]
    assert table["two slowest: change"].to_numpy() == pytest.approx([102 / 104 - 1, 262.5 / 250 - 1])
    assert list(table["quasi-static (< 5 %)"]) == ["yes", "no"]
    text = bounds.verdict_text(table, pd.DataFrame())
    assert "still changes by up to 5.0 % (X/X0 = 1, strain 0.10)" in text and "0.1 m/s curves are not yet" in text


def drained_summary():
    rows = []
    for lp, lost, s05 in ((1e-12, 1e-5, 100.0), (1e-9, 0.001, 99.0), (1e-6, 0.02, 70.0)):
        rows.append({"studies": "drainage rate_bounds", "dryness": 1.0, bounds.LP: lp, bounds.SPEED: 1.0,
                     "compression_time_us_at_0.10": 15.0, "smoothed_stress_kPa_at_0.05": s05,
                     "smoothed_stress_kPa_at_0.10": 2 * s05, "mass_lost_at_0.10": lost})
    return pd.DataFrame(rows)


def test_a_drained_cell_is_compared_with_the_closed_one_and_its_time_with_a_texture_analysers():
    table = bounds.drained_table(drained_summary())
    assert table["change at 0.05"].to_numpy() == pytest.approx([0, -0.01, -0.30])
    assert table["water lost by 0.10 [%]"].to_numpy() == pytest.approx([1e-3, 0.1, 2.0])
    # strain 0.10 reached 15 us after the plates started; a real cell (L_p 1e-12) takes L_p / 1e-12 times longer
    assert table["drains like a real cell in [s]"].to_numpy() == pytest.approx([15e-6, 15e-3, 15.0])
    text = bounds.drainage_text(table)
    assert "compared with the drained curves at L_p = 1e-06" in text  # 15 s lies within a test's 1-100 s
    assert "lost 2 % of its water" in text and "changed by -30 %" in text


def test_the_bounds_section_appears_only_in_a_run_with_those_studies():
    assert bounds.section({"studies": {"dryness_turgor": {}}}, drained_summary()) == ""
    html = bounds.section({"studies": {"drainage": {}}}, drained_summary())
    assert "Drained compression" in html and "toward the quasi-static" not in html.lower()


def test_an_overlaid_figure_draws_the_other_runs_curve_of_each_case_dashed_in_its_colour(root):
    config = yaml.safe_load((root / "config" / "config.yaml").read_text())
    spec = {"family": "curves", "study": "dryness_turgor", "x": "nominal_strain", "y": ["plate_stress_Pa"],
            "stage": "compression", "lines": "dryness", "title": "t"}
    config["figures"] = {"f": spec}
    strain = np.linspace(0, 0.1, 11)

    def series(factor):
        return pd.DataFrame([{"case": f"X{x}", "dryness": x, "stage": 1, "time_s": e, "nominal_strain": e,
                              "plate_stress_Pa": factor * x * e * 1e6} for x in (1.0, 0.5) for e in strain])
    band = {"X1.0": (strain[5:], 0.9 * 1e3 * strain[5:], 1.1 * 1e3 * strain[5:])}
    overlay = {"this": "converged", "lines": [(series(0.5), "paper's", "--"), (series(0.25), "closed cell", ":")],
               "band": band, "band_label": "shaded: its band"}
    figure = curves.draw(config, "f", series(1.0), root, overlay=overlay)
    ax = figure.axes[0]
    drawn = lambda style: [ln for ln in ax.get_lines() if ln.get_linestyle() == style and len(ln.get_xdata())]  # noqa: E731
    solid, dashed, dotted = drawn("-"), drawn("--"), drawn(":")
    assert len(solid) == len(dashed) == len(dotted) == 2
    for s, d, o in zip(solid, dashed, dotted):
        assert s.get_color() == d.get_color() == o.get_color()
        assert np.asarray(d.get_ydata()) == pytest.approx(0.5 * np.asarray(s.get_ydata()))
        assert np.asarray(o.get_ydata()) == pytest.approx(0.25 * np.asarray(s.get_ydata()))
    shaded = [c for c in ax.collections if len(c.get_paths()) and len(c.get_paths()[0].vertices)]
    assert len(shaded) == 1  # the one case with a band, from strain 0.05 on
    assert shaded[0].get_paths()[0].vertices[:, 0].min() == pytest.approx(0.05)
    labels = [t.get_text() for t in figure.axes[-1].get_legend().get_texts()]
    assert {"solid: converged", "dashed: paper's", "dotted: closed cell", "shaded: its band"} <= set(labels)


def test_a_speed_or_a_closed_cell_that_did_not_run_leaves_its_entries_empty():
    summary = rate_summary({(1.0, 1): (120, 300), (1.0, 0.5): (110, 280), (0.1, 0.5): (40, 90), (0.1, 0.25): (38, 85)})
    table = bounds.quasi_static_table(summary)
    assert list(table.columns[2:5]) == ["1 m/s [kPa]", "0.5 m/s [kPa]", "0.25 m/s [kPa]"]
    fresh, dried = table[table["X/X0"] == 1.0], table[table["X/X0"] == 0.1]
    assert np.isnan(fresh["0.25 m/s [kPa]"]).all() and np.isnan(dried["1 m/s [kPa]"]).all()
    assert fresh["two slowest: change"].to_numpy() == pytest.approx([110 / 120 - 1, 280 / 300 - 1])
    assert dried["two slowest: change"].to_numpy() == pytest.approx([38 / 40 - 1, 85 / 90 - 1])
    drained = bounds.drained_table(drained_summary().iloc[1:])  # the closed cell did not run
    assert drained["change at 0.05"].isna().all() and (drained["water lost by 0.10 [%]"] > 0).all()
    assert "lost 2 % of its water by strain 0.10 (X/X0 = 1). " in bounds.drainage_text(drained)


def test_the_other_runs_case_is_the_one_of_the_same_study_and_values_whatever_its_name(root, tmp_path):
    """converged.yaml's thickest wall runs at 0.9 ns (its wall limit at level 2), which its name says
    (dt0.9); the paper's run names it without: the other run's manifest finds it by its study and the
    values that study varies. A case the manifest does not hold is looked for by its name, also where its
    study matches no row (the slow workflow test met that: a frame filtered to nothing lost its columns)."""
    config = workflow_config(root, ["config/converged.yaml"])
    config["compare_with"]["output_dir"] = str(tmp_path)
    cases = matrix.expand(config)
    thick, fresh = cases["D150_dt0.9_G18_P200_t100_v1_X1"], cases["D150_G18_P200_t6_v1_X1"]
    (tmp_path / "runs").mkdir()
    for name in ("D150_G18_P200_t100_v1_X1", "D150_G18_P200_t12_v1_X1", "D150_G18_P200_t6_v1_X1"):
        (tmp_path / "runs" / f"{name}.h5").write_text("")
    pd.DataFrame([{"case": n, "studies": "wall_thickness", "dryness": 1.0, "t0_um": t, "plate_speed_m_s": 1.0,
                   "result": f"{tmp_path}/runs/{n}.h5"}
                  for n, t in (("D150_G18_P200_t12_v1_X1", 12.0), ("D150_G18_P200_t100_v1_X1", 100.0))]
                 ).to_csv(tmp_path / "manifest.csv", index=False)
    slow = next(c for c in cases.values() if c.values.get("plate_speed_m_s") == 10 and "plate_speed" in c.studies)
    found = comparison.other_runs(config, {thick.name: thick, fresh.name: fresh, slow.name: slow})
    assert slow.name not in found  # its study is not in the manifest, nor its name in runs/
    assert found[thick.name] == f"{tmp_path}/runs/D150_G18_P200_t100_v1_X1.h5"
    assert found[fresh.name] == f"{tmp_path}/runs/D150_G18_P200_t6_v1_X1.h5"  # not in the manifest: its name
    (tmp_path / "manifest.csv").unlink()
    assert thick.name not in comparison.other_runs(config, {thick.name: thick})  # no manifest: by name, not there
