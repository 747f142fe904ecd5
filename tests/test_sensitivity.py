"""The sensitivity target's parts on their own (issue 70): the design (analysis/design.py), the emulator
(analysis/emulator.py) against scikit-learn's own prediction and on held-out points of a known function, and
the Sobol estimators (analysis/sobol.py) against the Ishigami function's analytic indices."""
import copy
import math

import numpy as np
import pytest
import yaml
from sklearn.gaussian_process import GaussianProcessRegressor
from sklearn.gaussian_process.kernels import RBF, ConstantKernel, WhiteKernel

from analysis import design, emulator, matrix, sobol


@pytest.fixture(scope="module")
def config(root):
    return yaml.safe_load((root / "config" / "config.yaml").read_text())


def test_the_design_fills_its_ranges_and_scales_what_a_factor_carries(config):
    spec = config["studies"]["sensitivity"]["design"]
    points = design.points(spec)
    train = [v for role, v in points if role == "train"]
    held = [v for role, v in points if role == "held_out"]
    assert len(train) == spec["points"] and len(held) == spec["held_out"]
    assert not {tuple(v.values()) for v in train} & {tuple(v.values()) for v in held}
    for factor, fspec in spec["factors"].items():
        values = np.array([v[factor] for v in train])
        low, high = fspec["range"]
        assert values.min() >= low and values.max() <= high
        # quasi-random: every quarter of the (log) range holds a quarter of the points, within 4
        u = np.array([design.factor_to_unit(v, fspec) for v in values])
        assert all(abs(np.sum((u >= q / 4) & (u < (q + 1) / 4)) - len(u) / 4) <= 4 for q in range(4)), factor
    cases = matrix.expand(config)
    names = matrix.target_cases(config, cases, "sensitivity")
    assert len(names) == spec["points"] + spec["held_out"] + 1  # and the check point
    for name in names[:20]:
        case = cases[name].case
        ratio = case["cell"]["diameter_um"] / 150
        assert case["cell"]["n_wall"] == round(2067 * ratio ** 2), name  # the wall's spacing kept
        assert case["drying"]["ramp_time_us"] == pytest.approx(20 * ratio, rel=1e-3)
        assert case["fluid"]["model"] == "cavity" and case["time"]["scheme"] == "dynamic"
        assert case["compression"]["steps"] == 45000


def test_log_factors_map_to_and_from_the_unit_interval():
    spec = {"range": [0.18, 18], "scale": "log"}
    assert design.unit_to_factor(0.5, spec) == pytest.approx(1.8)
    assert design.factor_to_unit(1.8, spec) == pytest.approx(0.5)
    assert design.factor_to_unit(0.18, {"range": [0.1, 1.0]}) == pytest.approx(0.0888889)


@pytest.mark.parametrize("change, named", [
    (lambda d: d["factors"]["G_MPa"].pop("range"), "studies.sensitivity.design.factors.G_MPa: no range"),
    (lambda d: d["factors"].update({"porosity": {"range": [0, 1]}}), "factors.porosity: not an axis with a key"),
    (lambda d: d["factors"]["K_MPa"].update({"range": [0, 640]}), "a log scale needs low > 0"),
    (lambda d: d["factors"]["turgor_kPa"].update({"range": [300, 100]}), "is not low < high"),
    (lambda d: d["check"].update({"G_MPa": 50}), "check.G_MPa = 50: outside its range"),
])
def test_a_design_that_cannot_be_made_is_refused_naming_the_key(config, change, named):
    bad = copy.deepcopy(config)
    change(bad["studies"]["sensitivity"]["design"])
    with pytest.raises(matrix.ConfigError, match=named.replace(".", r"\.").replace("[", r"\[")):
        matrix.check(bad)


def smooth(u):
    """A known answer over [0, 1]^3 with a nonlinearity, an interaction and a factor that does nothing."""
    return np.exp(0.8 * u[:, 0]) + np.sin(3 * u[:, 1]) * u[:, 0] + 0.0 * u[:, 2]


def test_the_emulators_own_prediction_is_scikit_learns():
    rng = np.random.default_rng(1)
    x = rng.random((40, 3))
    y = smooth(x) + 0.01 * rng.standard_normal(40)
    em = emulator.fit(x, y)
    kernel = (ConstantKernel(em["constant"], "fixed") * RBF(em["length_scales"], "fixed")
              + WhiteKernel(em["noise"], "fixed"))
    gp = GaussianProcessRegressor(kernel, normalize_y=True, optimizer=None).fit(x, y)
    probe = rng.random((25, 3))
    mean, sd = emulator.predict(em, probe)
    sk_mean, sk_sd = gp.predict(probe, return_std=True)
    assert np.max(np.abs(mean - sk_mean)) < 1e-9 and np.max(np.abs(sd - sk_sd)) < 1e-9
    assert np.allclose(emulator.predict_mean(em, probe), mean, atol=1e-12)


def test_the_held_out_check_passes_a_good_emulator_and_fails_a_starved_one():
    rng = np.random.default_rng(2)
    x, held = design.unit_points(64, 3, 5), design.unit_points(32, 3, 6)
    good = emulator.held_out_check(emulator.fit(x, smooth(x)), held, smooth(held))
    assert good["q2"] > 0.99 and good["coverage_95"] >= 0.9
    few = rng.random((4, 3))
    starved = emulator.held_out_check(emulator.fit(few, smooth(few)), held, smooth(held))
    assert starved["q2"] < 0.9  # four points cannot learn the curve


def ishigami(u, a=7.0, b=0.1):
    x = -math.pi + 2 * math.pi * u
    return np.sin(x[:, 0]) + a * np.sin(x[:, 1]) ** 2 + b * x[:, 2] ** 4 * np.sin(x[:, 0])


def test_sobol_indices_of_the_ishigami_function_are_its_analytic_ones():
    """Ishigami & Homma 1990: a = 7, b = 0.1 give S = (0.3139, 0.4424, 0), S_T = (0.5576, 0.4424, 0.2437)."""
    first, total = sobol.indices(ishigami, 3, 2 ** 15, seed=3)
    assert np.allclose(first, [0.3139, 0.4424, 0.0], atol=0.02)
    assert np.allclose(total, [0.5576, 0.4424, 0.2437], atol=0.02)


def test_one_at_a_time_shares_match_the_first_order_for_an_additive_function_only():
    additive = lambda u: 3 * u[:, 0] + u[:, 1] ** 2  # noqa: E731
    first, _ = sobol.indices(additive, 2, 2 ** 14, seed=4)
    assert np.allclose(sobol.one_at_a_time(additive, np.array([0.5, 0.5])), first, atol=0.02)
    # Ishigami's x3 acts only through x1: one at a time from x1 = 0 (sin 0 = 0) it seems to do nothing
    assert sobol.one_at_a_time(ishigami, np.array([0.5, 0.5, 0.5]))[2] < 1e-12


def test_an_overconfident_emulator_is_widened_to_its_held_out_errors_and_a_modest_one_is_not():
    x, held = design.unit_points(16, 3, 5), design.unit_points(32, 3, 6)
    em = emulator.fit(x, smooth(x))
    mean, sd = emulator.predict(em, held)
    widened = emulator.widened_to_held_out(em, held, smooth(held))
    z = (smooth(held) - mean) / sd
    assert widened["sd_scale"] == pytest.approx(max(1.0, np.sqrt(np.mean(z ** 2))))
    _, wide_sd = emulator.predict(widened, held)
    assert np.mean(((smooth(held) - mean) / wide_sd) ** 2) <= 1.0 + 1e-9
    honest = emulator.widened_to_held_out(em, held, mean + 0.1 * sd)  # runs well inside the band
    assert honest["sd_scale"] == 1.0
