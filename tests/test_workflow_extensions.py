"""The extensions target end to end on reduced cells (tests/extensions_reduced.yaml): the loops of the
elastic and the elastic-plastic wall with their set and dissipation, the ensembles' tables and claims,
its four figures (the bands drawn from their members), its page, and none of the default target's.
Slow: a few minutes on 2 cores."""
import numpy as np
import pandas as pd
import pytest

from conftest import check_target_page, reduced_target_fixture

pytestmark = pytest.mark.slow
REDUCED = "tests/extensions_reduced.yaml"
extensions_run = reduced_target_fixture("extensions", REDUCED)


def test_the_plastic_wall_keeps_a_larger_set_and_its_flow_takes_part_of_the_loops_energy(extensions_run):
    loops = pd.read_csv(extensions_run / "tables" / "extensions" / "page" / "load_unload.csv").set_index("wall")
    assert sorted(loops.index) == ["elastic", "plastic"]
    elastic, plastic = loops.loc["elastic"], loops.loc["plastic"]
    # It turns at strain 0.08 (the records, every 200 steps, may just miss the turn)
    assert loops["unloaded from"].between(0.075, 0.09).all() and (loops["permanent set"] < loops["unloaded from"]).all()
    assert plastic["permanent set"] > elastic["permanent set"] + 0.01
    assert elastic["by plastic flow [nJ]"] == 0 and elastic["plastic strain, end (mean)"] == 0
    assert 0.1 < plastic["plastic share"] < 1 and plastic["plastic strain, end (mean)"] > 0
    assert (loops["loop dissipated [nJ]"] > 0).all()


def test_the_ensembles_are_summarised_by_mean_and_band_and_the_claims_judged_on_the_mean(extensions_run):
    page = extensions_run / "tables" / "extensions" / "page"
    table = pd.read_csv(page / "ensemble.csv")
    stress = table[table["quantity"] == "stress at 0.05 [kPa]"]
    assert sorted(stress["dryness"]) == [0.1, 1.0] and (table["members"] == 3).all()
    assert stress["mean"].gt(0).all() and stress["homogeneous"].gt(0).all()
    assert stress["CV of members"].between(0, 0.5).all()
    claims = pd.read_csv(page / "ensemble_claims.csv")
    assert len(claims) == 2 and set(claims["verdict"]) <= {"agree", "disagree"}
    assert claims["members agreeing"].str.endswith("of 3").all()
    growth = pd.read_csv(page / "band_growth.csv")
    assert list(growth["CV of the properties"]) == [0.1, 0.1, 0.3, 0.3]
    assert np.isfinite(growth[growth["strain"] == 0.05]["band width / mean"]).all()  # the reduced runs stop at 0.1


def test_page_and_figures_are_written_and_the_default_target_is_not(root, extensions_run, tmp_path):
    check_target_page(root, extensions_run, "extensions", REDUCED, "extensions.html",
                      ["Load-unload: elastic and elastic-plastic walls", "Heterogeneous cells: mean and band",
                       "The paper's claims on the ensemble's mean"], ["ext01", "ext02", "ext03", "ext04"], tmp_path)
