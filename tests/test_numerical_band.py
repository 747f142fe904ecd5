"""The default figures' numerical band (analysis/numerical_band.py): the LJ ladder's table read, its changes
computed, and stated in the captions and claims only where the run is the ladder's level 1."""
import copy

import numpy as np
import pandas as pd
import pytest

from analysis import matrix, numerical_band, report


def ladder(**values):
    """A small ladder: stress at 0.05 of 100, 110, 99 kPa at levels 1-3 (the other columns follow it)."""
    rows = []
    for dryness in numerical_band.DRYNESS:
        for level, stress in ((1, 100.0), (2, 110.0), (3, 99.0)):
            row = {"dryness": dryness, "level": level, "n_wall": 2067 * 2 ** (level - 1), "n_fluid": 3082 * level,
                   "dt_ns": 1 if level < 3 else 0.5}
            row.update({column: stress * dryness for column in numerical_band.QUANTITIES})
            rows.append(row)
    return pd.DataFrame(rows)


@pytest.fixture(scope="module")
def config(root):
    return matrix.workflow_config([], root)


def test_the_change_between_levels_is_the_ratio_of_the_table():
    table = ladder()
    assert numerical_band.change(table, "smoothed_stress_kPa_at_0.05", 0.5) == pytest.approx(0.10)
    assert numerical_band.change(table, "peak_force_top_uN", 1.0, 2, 3) == pytest.approx(-0.10)
    assert np.isnan(numerical_band.change(table, "peak_force_top_uN", 0.3))  # a dryness the ladder has not


def test_a_figure_is_bounded_by_what_it_plots(config):
    columns = {fig: numerical_band.columns_of(config["figures"][fig]) for fig in ("fig07", "fig14", "fig04", "fig02", "fig05")}
    assert columns["fig07"] == ["smoothed_stress_kPa_at_0.05", "smoothed_stress_kPa_at_0.10"]
    assert columns["fig14"] == ["peak_force_top_uN"]
    assert columns["fig04"] == ["dried_A_over_A0", "dried_V_over_V0"]
    assert columns["fig02"] == numerical_band.SHAPE and columns["fig05"] == ["compression_time_us_at_0.10"]


def test_the_caption_states_both_steps_of_the_ladder(config):
    text = numerical_band.caption(ladder(), config["figures"]["fig07"], "ladder.csv")
    assert "from level 1 to 2, the stress at strain 0.05 by +10.0 % / +10.0 % / +10.0 %" in text
    assert "from level 2 to 3, the stress at strain 0.05 by -10.0 %" in text and "ladder.csv" in text


def test_the_shipped_band_is_the_ladder_of_every_default_figure(root, config):
    """The committed table has the three levels at the three dryness levels, and every default figure's
    caption in the report states a finite change for it."""
    band = numerical_band.for_run(config, root)
    assert band is not None and len(band) == 9 and sorted(set(band["level"])) == [1, 2, 3]
    cases = matrix.expand(config)
    for fig in matrix.target_figures(config):
        text = report.caption(config, fig, cases, band)
        assert "Numerical band" in text and "not run" not in text, fig
        assert len(numerical_band.columns_of(config["figures"][fig])) >= 1


def test_no_band_where_the_run_is_not_the_ladders_level_1(root, config):
    for change in ({"coupling": {"model": "pressure"}}, {"cell": {"n_wall": 4134}}, {"time": {"dt_ns": 0.5}}):
        other = copy.deepcopy(config)
        for section, values in change.items():
            other["base"].setdefault(section, {}).update(values)
        assert numerical_band.for_run(other, root) is None, change
    assert numerical_band.for_run({k: v for k, v in config.items() if k != "numerical_band"}, root) is None


def test_a_ladder_table_without_a_quantity_is_refused(tmp_path):
    path = tmp_path / "ladder.csv"
    ladder().drop(columns=["peak_force_top_uN"]).to_csv(path, index=False)
    with pytest.raises(ValueError, match="lacks \\['peak_force_top_uN'\\]"):
        numerical_band.read(path)


def test_the_claims_table_shows_the_band_where_the_rows_carry_it(root, config):
    band = numerical_band.for_run(config, root)
    row = {"claim": "Fresh cells are stiffer", "figure": "7", "measured": "ratio", "value": 2.3, "threshold": "> 1",
           "verdict": "agree", "point_value": 2.5, "note": ""}
    plain = report.claims_table([row])
    banded = report.claims_table([dict(row, level_1_to_2=numerical_band.claim_band(band, "7", config))])
    assert "numerical band" not in plain
    assert "<th>numerical band: level 1 to 2</th>" in banded and "from level 1 to 2, the stress at strain 0.05 by" in banded
    assert numerical_band.claim_band(band, "11-12", config) == numerical_band.claim_band(band, "11", config)
