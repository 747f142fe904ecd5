"""The sensitivity and calibrate targets end to end on reduced cells and small designs
(tests/sensitivity_reduced.yaml): their runs, tables, figures and pages; the slider page opened in headless
Chromium at the design's check point gives the prediction the target wrote beside the full run there; and
the calibration's run at the posterior's median. Slow: about a minute on 2 cores."""
import shutil

import numpy as np
import pandas as pd
import pytest
from PIL import Image

from conftest import CI, emulator_page_prediction, reduced_target_fixture, run_workflow, workflow_config

pytestmark = pytest.mark.slow
REDUCED = "tests/sensitivity_reduced.yaml"
sensitivity_run = reduced_target_fixture("sensitivity", REDUCED)
CHROMIUM = shutil.which("chromium")


def test_the_design_runs_the_emulators_and_the_sobol_table(root, sensitivity_run):
    config = workflow_config(root, CI + [REDUCED], sensitivity_run)
    design = pd.read_csv(sensitivity_run / "tables" / "design" / "sensitivity.csv")
    assert design["role"].value_counts().to_dict() == {"train": 8, "held_out": 4, "check": 1}
    assert (design["strain_reached"] >= 0.21).all() and (design["stress_kPa_at_0.20"] > 0).all()
    held = pd.read_csv(sensitivity_run / "tables" / "sensitivity" / "held_out.csv")
    assert len(held) == 13 and held["runs"].eq(4).all()  # 4 answers and the 9 other strains of the curve
    sobol = pd.read_csv(sensitivity_run / "tables" / "sensitivity" / "sobol.csv")
    assert len(sobol) == 4 * len(config["studies"]["sensitivity"]["design"]["factors"])
    assert (sobol["total"] >= sobol["first"] - 0.05).all()  # a factor's total holds its first order
    assert ((sobol["first_low"] <= sobol["first"] + 1e-9) & (sobol["first"] <= sobol["first_high"] + 1e-9)).all()
    assert np.allclose(sobol.groupby("answer")["one_at_a_time"].sum(), 1.0)
    for name in ("sensitivity_indices", "sensitivity_held_out"):
        with Image.open(sensitivity_run / "figures" / f"{name}.png") as image:
            assert image.width > 600 and image.height > 500
    page = (sensitivity_run / "report" / "sensitivity.html").read_text()
    for heading in ("The emulators on held-out runs", "Sobol indices", "The slider page's setting against a full run"):
        assert heading in page


@pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed: scripts/setup installs it")
def test_the_slider_page_at_the_check_point_gives_the_targets_prediction(root, sensitivity_run, tmp_path):
    config = workflow_config(root, CI + [REDUCED], sensitivity_run)
    check = config["studies"]["sensitivity"]["design"]["check"]
    fragment = "&".join(f"{k}={v}" for k, v in check.items())
    status, rows = emulator_page_prediction(sensitivity_run / "report" / "emulator.html", fragment)
    assert status.startswith("predicted at "), status
    written = pd.read_csv(sensitivity_run / "tables" / "sensitivity" / "check_point.csv")
    assert np.allclose(rows[:, 1], written["median_kPa"], rtol=1e-6)
    assert np.allclose(rows[:, 2], written["low_kPa"], rtol=1e-6) and np.allclose(rows[:, 3], written["high_kPa"], rtol=1e-6)
    assert written["run_kPa"].gt(0).all()  # the full run at that setting, beside it


def test_calibrate_writes_a_posterior_its_diagnostics_and_a_run_at_its_median(root, sensitivity_run):
    run_workflow(root, sensitivity_run, CI + [REDUCED], "calibrate")
    cal = sensitivity_run / "tables" / "calibration"
    posterior = pd.read_csv(cal / "posterior.csv")
    assert list(posterior["unknown"]) == ["contraction_N_m", "G_MPa", "t0_um", "contraction_ratio"]
    assert ((posterior["prior_low"] <= posterior["p05"]) & (posterior["p05"] <= posterior["median"])
            & (posterior["median"] <= posterior["p95"]) & (posterior["p95"] <= posterior["prior_high"])).all()
    confirm = pd.read_csv(cal / "confirm.csv")
    assert sorted(confirm["target"]) == ["dried_cell_volume", "pressure_probe_modulus"]
    assert confirm["run_at_median"].gt(0).all()
    text = (sensitivity_run / "report" / "calibrate.html").read_text()
    for heading in ("The targets", "The posterior", "acceptance", "A full run at the posterior's median",
                    "Recovery of a held-out run's parameters"):
        assert heading in text
    assert "Karunasena" in text  # each target with its provenance
