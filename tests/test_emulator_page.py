"""The emulator's slider page (analysis/emulator_page.py) in headless Chromium: a setting given in the page's
address is predicted in the page, in JavaScript, as analysis/emulator.py predicts it in Python; a setting
outside a factor's range is refused in the page's status; the page fetches nothing."""
import shutil

import numpy as np
import pytest

from analysis import design, emulator, emulator_page, sensitivity
from analysis.design_runs import STRAINS, STRESS_OUTPUTS
from conftest import emulator_page_prediction

CHROMIUM = shutil.which("chromium")
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed: scripts/setup installs it")

SPEC = {"factors": {"dryness": {"range": [0.1, 1.0]}, "G_MPa": {"range": [0.18, 18], "scale": "log"}}}
CONFIG = {"axes": {"dryness": {"key": "drying.dryness", "title": "X/X0"},
                   "G_MPa": {"key": "wall.G_MPa", "title": "G [MPa]"}},
          "base": {"drying": {"dryness": 1.0}, "wall": {"G_MPa": 18}}}


def stress(u, strain):
    """A stand-in stress curve [kPa] over (dryness, ln G): stiffer fresh and with a stiffer wall."""
    return (20 + 400 * strain ** 1.5) * (0.4 + u[:, 0]) * np.exp(0.6 * u[:, 1]) * (1 + 0.1 * np.sin(5 * u[:, 0]))


@pytest.fixture(scope="module")
def emulators():
    x = design.unit_points(32, 2, 1)
    return {c: emulator.fit(x, stress(x, e), "log", restarts=1) for c, e in zip(STRESS_OUTPUTS, STRAINS)}


def open_page(tmp_path, emulators, fragment):
    page, data = tmp_path / "emulator.html", tmp_path / "emulator.data.js"
    emulator_page.write(page, data, sensitivity.page_data(CONFIG, "test", SPEC, emulators), "a test")
    assert "http" not in page.read_text() and "http" not in data.read_text(), "the page must not fetch anything"
    return emulator_page_prediction(page, fragment)


def test_a_setting_in_the_address_is_predicted_in_the_page_as_in_python(tmp_path, emulators):
    values = {"dryness": 0.37, "G_MPa": 2.9}  # no design point
    status, page = open_page(tmp_path, emulators, "dryness=0.37&G_MPa=2.9")
    assert status == "predicted at dryness=0.37&amp;G_MPa=2.9", status
    python = sensitivity.predicted_curve(SPEC, emulators, values)
    assert page.shape == (10, 4)
    assert np.allclose(page[:, 0], STRAINS)
    for k, column in enumerate(("median_kPa", "low_kPa", "high_kPa"), start=1):
        assert np.allclose(page[:, k], python[column].to_numpy(), rtol=1e-6), column
    # and the emulator has learned the stand-in: its median within 3 % of the function there
    u = np.array([[design.factor_to_unit(0.37, SPEC["factors"]["dryness"]),
                   design.factor_to_unit(2.9, SPEC["factors"]["G_MPa"])]])
    truth = np.array([stress(u, e)[0] for e in STRAINS])
    assert np.allclose(page[:, 1], truth, rtol=0.03)


def test_a_setting_outside_the_ranges_is_refused_in_the_page(tmp_path, emulators):
    status, _ = open_page(tmp_path, emulators, "dryness=1.5")
    assert status.startswith("error: dryness = 1.5 is outside its range 0.1,1"), status
