"""The convergence target end to end on reduced cells (tests/convergence_reduced.yaml): its runs, its
table and page, its figures, and none of the default target's. Slow: about two minutes on 2 cores."""
import pandas as pd
import pytest

from analysis import matrix
from conftest import CI, run_reduced_target, workflow_config
from figure_checks import check_figures

pytestmark = pytest.mark.slow
REDUCED = "tests/convergence_reduced.yaml"


@pytest.fixture(scope="module")
def convergence_run(root, tmp_path_factory):
    return run_reduced_target(root, tmp_path_factory.mktemp("convergence results"), "convergence", REDUCED)


def test_table_has_every_refinement_with_its_changes(convergence_run):
    table = pd.read_csv(convergence_run / "tables" / "convergence" / "convergence.csv")
    resolution = table[table["study"] == "convergence_resolution"]
    assert list(resolution["resolution"]) == [1, 2] and list(resolution["n_fluid"]) == [700, 1980]
    time_step = table[table["study"] == "convergence_time_step"]
    assert sorted(zip(time_step["coupling"], time_step["dt_ns"])) == [
        ("lennard_jones", 0.5), ("lennard_jones", 1.0), ("pressure", 0.5), ("pressure", 1.0)]
    ladder = table[table["study"] == "pressure_resolution"]
    assert list(ladder["resolution"]) == [1, 2] and set(ladder["coupling"]) == {"pressure"}
    assert ladder["dt_ns"].eq(0.5).all()  # one time step at every level
    sweeps = {study: sorted(rows[rows["refined_axis"].iloc[0]]) for study, rows in table.groupby("study")
              if study in ("smoothing_ratio", "bulk_modulus", "fast_plates")}
    assert sweeps == {"smoothing_ratio": [0.888, 1.2], "bulk_modulus": [20, 40], "fast_plates": [1, 5]}
    for (study, coupling, dryness), group in table.groupby(["study", "coupling", "dryness"]):
        changes = group["change_smoothed_stress_kPa_at_0.05"].notna().sum()
        assert changes == len(group) - 1, (study, coupling, dryness)  # one per pair of successive cases
    assert table["smoothed_stress_kPa_at_0.05"].gt(0).all()
    assert table["load_fluid_share"].between(0, 1.5).all()
    pressure = table[table["coupling"] == "pressure"]
    assert pressure["compression_energy_residual_over_work"].abs().lt(0.01).all()  # the account closes
    assert pressure["load_backstop_share"].between(0, 0.5).all()
    closed = table[table["study"].str.startswith("closed_cell")]
    assert set(closed["fluid"]) == {"cavity"} and set(closed["coupling"]) == {"-"}
    assert list(closed[closed["study"] == "closed_cell_resolution"]["n_wall"]) == [642, 1284]
    assert sorted(closed[closed["study"] == "closed_cell_bulk_modulus"]["K_MPa"]) == [20, 2200]
    assert closed["compression_energy_residual_over_work"].abs().lt(1e-6).all()  # closes by construction


def test_anchors_table_has_each_anchor_against_its_analytic_value(convergence_run):
    anchors = pd.read_csv(convergence_run / "tables" / "convergence" / "anchors.csv")
    assert set(anchors["anchor"]) == {"breathing mode", "Young-Laplace", "membrane force"}
    assert (anchors["analytic"] > 0).all() and anchors["measured / analytic"].notna().sum() >= len(anchors) - 1
    laplace = anchors[anchors["anchor"] == "Young-Laplace"]
    assert sorted({q.split(" at ")[1] for q in laplace["quantity"]}) == ["200 kPa [kPa]", "2000 kPa [kPa]"]
    assert laplace["met"].all()  # a cell at rest meets Young-Laplace at any resolution


def test_page_and_figures_are_written_and_the_default_target_is_not(root, convergence_run, tmp_path):
    page = (convergence_run / "report" / "convergence.html").read_text()
    for section in ("Verdicts", "Analytic anchors", "Resolution convergence", "Time-step convergence",
                    "The two wall-fluid couplings", "Resolution convergence, pressure coupling",
                    "The closed cell, quasi-static: two resolutions"):
        assert section in page, section
    config = workflow_config(root, CI + [REDUCED], convergence_run)
    figures = matrix.target_figures(config, "convergence")
    assert figures == [f"conv{n:02d}" for n in range(1, 13)]
    check_figures(config, convergence_run, root, tmp_path, figures)
    for fig in figures:
        assert f"figures/{fig}.png" in page
    assert not (convergence_run / "figures" / "fig01.png").exists()
    assert not (convergence_run / "report" / "index.html").exists()
