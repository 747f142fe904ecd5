"""The calibration (analysis/calibration.py) on a model whose answer is known (issue 70's recovery test): data
made at known parameters with noise are recovered within their posterior interval; with no information the
posterior is the prior; and what cannot be trusted is refused, naming it."""
import copy

import numpy as np
import pandas as pd
import pytest
import yaml
from scipy import stats

from analysis import calibration, design, emulator

FACTORS = {"k": {"range": [30, 30000], "scale": "log"}, "g": {"range": [0.18, 18], "scale": "log"}}


def model(u):
    """A stand-in cell over the unit square of (k, g): a stiffness that grows with k and a little with g,
    and a shrinkage that g sets: two answers, each mostly one unknown's."""
    return {"eps": np.exp(0.5 + 4.0 * u[:, 0] + 0.5 * u[:, 1]), "vv0": 0.15 + 0.2 * u[:, 1] ** 1.5}


def emulators_of(points=64, seed=7):
    x = design.unit_points(points, 2, seed)
    y = model(x)
    return {"eps@dryness=1": emulator.fit(x, y["eps"], "log"), "vv0@dryness=0.1": emulator.fit(x, y["vv0"])}


def posterior_of(targets, ems, steps=1500):
    log_post = calibration.log_posterior_function(ems, targets, list(FACTORS), list(FACTORS))
    flat, diagnostics = calibration.sample(log_post, 2, {"walkers": 24, "steps": steps, "burn": 500, "seed": 4})
    return calibration.to_values(flat, list(FACTORS), FACTORS), flat, diagnostics


def test_parameters_that_made_the_data_are_recovered_within_their_posterior_interval():
    ems = emulators_of()
    truth_unit = np.array([[0.62, 0.35]])
    rng = np.random.default_rng(5)
    made = model(truth_unit)
    eps_sd_ln, vv0_sd = 0.05, 0.004
    targets = [("probe", "eps@dryness=1", float(made["eps"][0] * np.exp(eps_sd_ln * rng.standard_normal())), eps_sd_ln, "log"),
               ("shrink", "vv0@dryness=0.1", float(made["vv0"][0] + vv0_sd * rng.standard_normal()), vv0_sd, "none")]
    samples, _flat, diagnostics = posterior_of(targets, ems)
    table = calibration.posterior_table(samples, list(FACTORS), FACTORS)
    truth = {f: design.unit_to_factor(u, FACTORS[f]) for f, u in zip(FACTORS, truth_unit[0])}
    for _, row in table.iterrows():
        assert row["p05"] <= truth[row["unknown"]] <= row["p95"], (row.to_dict(), truth)
        # informative: the 90 % interval is far narrower than the prior's
        assert np.log(row["p95"] / row["p05"]) < 0.3 * np.log(row["prior_high"] / row["prior_low"]), row.to_dict()
    assert 0.2 < diagnostics["acceptance_mean"] < 0.8
    assert diagnostics["kept_over_autocorrelation"] > 20


def test_with_data_that_say_nothing_the_posterior_is_the_prior():
    """A target a million times wider than any answer leaves the prior: each unknown's unit coordinate is
    uniform (Kolmogorov-Smirnov on thinned samples)."""
    ems = emulators_of()
    targets = [("nothing", "vv0@dryness=0.1", 0.2, 1e6, "none")]
    _samples, flat, diagnostics = posterior_of(targets, ems, steps=3000)
    thinned = flat[:: max(1, int(24 * max(diagnostics["autocorrelation_steps"])))]
    for i in range(2):
        assert stats.kstest(flat[::50, i], "uniform").pvalue > 0.01
        assert 0.4 < np.median(flat[:, i]) < 0.6
    assert len(thinned) >= 10


@pytest.fixture()
def config(root):
    return yaml.safe_load((root / "config" / "config.yaml").read_text())


@pytest.mark.parametrize("change, named", [
    (lambda c: c["calibration"]["targets"]["dried_cell_volume"].pop("sigma"),
     "calibration.targets.dried_cell_volume: no uncertainty"),
    (lambda c: c["calibration"]["unknowns"].append("turgor_kPa"),
     "calibration.unknowns: 'turgor_kPa' has no prior range"),
    (lambda c: c["calibration"]["targets"]["dried_cell_volume"].update({"sigma": 0}),
     "its uncertainty must be > 0"),
    (lambda c: c["calibration"]["targets"]["dried_cell_volume"].update({"where": {"dryness": 0.5}}),
     r"where.dryness = 0.5: studies.calibration runs dryness at \[1.0, 0.1\]"),
])
def test_what_cannot_be_calibrated_is_refused_naming_it(config, change, named):
    bad = copy.deepcopy(config)
    change(bad)
    with pytest.raises(calibration.CalibrationError, match=named):
        calibration.check(bad)


def test_an_emulator_worse_than_the_data_is_refused():
    def wiggly(u):  # a stiffness with a bump that eight runs cannot place
        return model(u)["eps"] * np.exp(0.8 * np.sin(9 * u[:, 0] * u[:, 1]))
    x = design.unit_points(8, 2, 8)
    held = design.unit_points(16, 2, 9)
    ems = {"eps@dryness=1": emulator.fit(x, wiggly(x), "log")}
    frame = {"eps@dryness=1": wiggly(held)}
    targets = [("probe", "eps@dryness=1", 20.0, 0.01, "log")]
    with pytest.raises(calibration.CalibrationError, match=r"misses its 16 held-out runs by .* more than the target's "
                                                             r"uncertainty 0.01"):
        calibration.judge_emulators(ems, pd.DataFrame(frame), held, targets)
    wide = [("probe", "eps@dryness=1", 20.0, 5.0, "log")]
    assert calibration.judge_emulators(ems, pd.DataFrame(frame), held, wide)["held_out_rmse"].iloc[0] < 5.0


def test_the_documented_way_to_add_a_measured_number_is_a_calibration_the_config_accepts(root, config):
    """docs/extending.md's example, merged over config.yaml as --configfile merges it."""
    from conftest import between_markers
    from analysis import matrix
    block = between_markers((root / "docs" / "extending.md").read_text(), "calibration-target")
    mine = yaml.safe_load(block.split("```yaml\n", 1)[1].split("```", 1)[0])
    merged = matrix.workflow_config([], root)
    merged["calibration"]["targets"].update(mine["calibration"]["targets"])
    _spec, unknowns, targets = calibration.check(merged)
    assert ("my_probe_modulus", "volumetric_modulus_MPa@dryness=1", 12.0, 0.3, "log") in targets
    assert len(targets) == 3 and unknowns == ["contraction_N_m", "G_MPa", "t0_um", "contraction_ratio"]


def test_a_curve_target_is_one_column_per_strain_and_a_strain_the_design_does_not_record_is_refused():
    curve = {"quantity": "stress_kPa", "where": {"dryness": 1.0}, "strains": [0.05, 0.10], "value": [40.0, 120.0],
             "sigma": [5.0, 12.0], "provenance": "a lab's single-cell compression"}
    assert calibration.target_columns("cell_curve", curve) == [
        ("stress_kPa_at_0.05@dryness=1", 40.0, 5.0, "none"), ("stress_kPa_at_0.10@dryness=1", 120.0, 12.0, "none")]
    with pytest.raises(calibration.CalibrationError, match=r"strains: \[0.07\] are not among the strains"):
        calibration.target_columns("cell_curve", {**curve, "strains": [0.05, 0.07]})
    with pytest.raises(calibration.CalibrationError, match="a curve needs as many strains, values and sigmas"):
        calibration.target_columns("cell_curve", {**curve, "sigma": [5.0]})
