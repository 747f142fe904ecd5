"""The claims in columns (analysis/columns.py): a column's band beyond strain 0.05 from the changes that
ran at a few dryness levels, every other case moved as its dryness's case moved, and the report's words
naming what tells two columns apart where a verdict changes. Synthetic compressions, stress linear in
strain, so every number below is arithmetic."""
import numpy as np
import pandas as pd
import pytest
import yaml

from analysis import aggregate, claims, columns, matrix
from test_analysis import synthetic_series

FRESH, DRIED = 1.0, 0.1


@pytest.fixture(scope="module")
def config(root):
    return yaml.safe_load((root / "config" / "config.yaml").read_text())


@pytest.fixture
def base(config):
    return {axis: matrix.base_value(config, axis) for axis in config["axes"]}


def table(config, base, cases):
    """(summary, series) of cases [(name, axis values over base, stiffness in kPa per unit strain)], each
    with the values its coupled keys set (level 3's dt_ns), as a run's summary has them."""
    rows, series = [], []
    for name, values, stiffness in cases:
        ts = synthetic_series(stiffness, name).assign(section_stress_Pa=np.nan, plate_top_z_m=-np.arange(22.0))
        series.append(ts)
        rows.append({**columns.values_of(config, base, values), "case": name, "studies": "s", "settle_volume_ratio": 1.001, **aggregate.summarise(ts)})
    return pd.DataFrame(rows), pd.concat(series, ignore_index=True)


def smoothed(series, case, strain):
    grid, stress = claims.stress_curve(series, case)
    return float(np.interp(strain, grid, stress))


def test_a_case_without_its_own_change_moves_as_its_dryness_did_beyond_005_only(config, base):
    """Level 3 ran at X/X0 = 1 (0.8 of level 2's stress) and 0.1 (0.5 of it): a 300 kPa cell keeps its
    stress below strain 0.05 and takes 0.8 beyond it when fresh, sqrt(0.8 x 0.5) halfway in dryness."""
    level3 = {"resolution": 3}
    summary, series = table(config, base, [
        ("X1", {"dryness": FRESH}, 1000.0), ("X0.1", {"dryness": DRIED}, 1000.0),
        ("X1_R3", {"dryness": FRESH, **level3}, 800.0), ("X0.1_R3", {"dryness": DRIED, **level3}, 500.0),
        ("X1_P300", {"dryness": FRESH, "turgor_kPa": 300}, 2000.0),
        ("X0.55_P300", {"dryness": 0.55, "turgor_kPa": 300}, 2000.0)])
    changed_summary, changed, measured = columns.changed_view(config, summary, series, base, {**base, **level3},
                                                              list(config["axes"]))
    assert sorted(measured) == [DRIED, FRESH]
    assert smoothed(changed, "X1_P300", 0.03) == pytest.approx(smoothed(series, "X1_P300", 0.03))
    assert smoothed(changed, "X1_P300", 0.12) == pytest.approx(0.8 * smoothed(series, "X1_P300", 0.12), rel=1e-9)
    halfway = np.sqrt(0.8 * 0.5)
    assert smoothed(changed, "X0.55_P300", 0.12) == pytest.approx(halfway * smoothed(series, "X0.55_P300", 0.12),
                                                                  rel=1e-9)
    # A case whose change ran is that run: its curve and its summary's numbers, under its own name.
    assert smoothed(changed, "X1", 0.03) == pytest.approx(0.8 * smoothed(series, "X1", 0.03))
    row = changed_summary[changed_summary["case"] == "X1"].iloc[0]
    assert row["stress_kPa_at_0.05"] == pytest.approx(0.8 * 1000 * 0.05)
    assert row["resolution"] == base["resolution"]  # its axis values stay the column's


def test_a_band_that_crosses_the_threshold_leaves_the_claim_undecided(config, base):
    """Fresh over dried, mean stress ratio: 1.25 at level 2 (agree, > 1). Level 3 reads the fresh cell at
    0.5 and the dried at 1.0 of level 2 beyond strain 0.05: a ratio below 1 there, so the band spans 1."""
    config = dict(config, claim_columns={"sph": {"label": "SPH", "where": {},
                                                 "band": {"l3": {"label": "level 2 to 3", "where": {"resolution": 3}}}}})
    summary, series = table(config, base, [
        ("X1", {"dryness": FRESH}, 1250.0), ("X0.1", {"dryness": DRIED}, 1000.0),
        ("X1_R3", {"dryness": FRESH, "resolution": 3}, 625.0), ("X0.1_R3", {"dryness": DRIED, "resolution": 3}, 1000.0)])
    rows = {r["claim"]: r for r in columns.evaluate(config, summary, series, base)["sph"]}
    stiffer = rows["Fresh cells are stiffer than extremely dried ones (X/X0 = 1.0 vs 0.1, 200 kPa)"]
    assert stiffer["verdict"] == "agree" and stiffer["value"] == pytest.approx(1.25)
    assert stiffer["band_low"] == pytest.approx(0.625) and stiffer["band_high"] == pytest.approx(1.25)
    assert stiffer["column_verdict"] == "band spans the threshold" and stiffer["band_changes"] == "level 2 to 3"


def test_a_band_within_the_threshold_keeps_the_verdict_and_an_unjudged_figure_says_why(config, base):
    config = dict(config, claim_columns={"closed": {
        "label": "closed", "where": {}, "not_judged": {"11-12": "no rate in the quasi-static scheme"},
        "band": {"l3": {"label": "level 2 to 3", "where": {"resolution": 3}}}}})
    summary, series = table(config, base, [
        ("X1", {"dryness": FRESH}, 2000.0), ("X0.1", {"dryness": DRIED}, 1000.0),
        ("X1_R3", {"dryness": FRESH, "resolution": 3}, 1800.0), ("X0.1_R3", {"dryness": DRIED, "resolution": 3}, 1000.0)])
    rows = {r["claim"]: r for r in columns.evaluate(config, summary, series, base)["closed"]}
    stiffer = rows["Fresh cells are stiffer than extremely dried ones (X/X0 = 1.0 vs 0.1, 200 kPa)"]
    assert stiffer["column_verdict"] == "agree" and stiffer["band_low"] > 1.0
    speed = rows["Faster plates give impulsive early stress peaks, weaker for drier cells"]
    assert speed["column_verdict"] == "not judged: no rate in the quasi-static scheme"


def test_the_plain_words_name_what_tells_two_columns_apart_where_a_verdict_changes(config):
    config = dict(config, claim_columns={
        "a": {"label": "column A", "where": {}, "differs_from_previous": "the numerics"},
        "b": {"label": "column B", "where": {"fluid": "cavity"}, "differs_from_previous": "the rate"}})
    first = [{"claim": "one", "figure": "7"}, {"claim": "two", "figure": "10"}, {"claim": "three", "figure": "15"}]
    verdicts = [["agree", "agree", "agree"], ["agree", "agree", "disagree"], ["not run", "band spans the threshold", "agree"]]
    text = columns.plain_words(config, first, verdicts, "the paper's configuration")
    hold, change = text.split("Change between columns")
    assert "one (fig 7): agree in all 3 columns" in hold and "two" not in hold
    assert "two (fig 10): column A: agree, column B: disagree (the rate)." in change
    assert "three (fig 15): its band spans the threshold in the column A." in change


def test_a_column_and_a_change_take_the_values_their_coupled_keys_set(root):
    """config/converged.yaml: the closed cell's `fluid` value sets time.dt_ns to 100 and level 3 sets 0.75,
    so the closed-cell column reads its cases at dt_ns 100, and the level-3 change finds the run at 0.75 ns
    (read at base's 1 ns, both would find nothing and every claim would read 'not run')."""
    from conftest import workflow_config
    config = workflow_config(root, ["config/converged.yaml"])
    base = {axis: matrix.base_value(config, axis) for axis in config["axes"]}
    assert columns.values_of(config, base, {"fluid": "closed_cell"})["dt_ns"] == 100
    assert columns.values_of(config, base, {"resolution": 3})["dt_ns"] == 0.75
    cases = columns.default_cases(config, matrix.expand(config))
    fresh = cases["D150_G18_P200_t6_v1_X1"]
    assert columns.counterpart_name(config, cases, fresh, {"resolution": 3}) == "D150_dt0.75_G18_P200_R3_t6_v1_X1"
    assert columns.counterpart_name(config, cases, fresh, {"fluid": "closed_cell", "K_MPa": 2200}) == \
        "D150_dt100_Fclosed_cell_G18_K2200_P200_t6_v1_X1"
