"""The drying stage at the paper's full resolution (issue: solver physics). Ten default 50 us
drying runs: each reaches a steady state on its target turgor, sizes order with dryness, and the
fresh cell satisfies the Young-Laplace balance. Slow: ~10 CPU-minutes before optimisation."""
import numpy as np
import pytest

from solver_runs import run_cases, timeseries

pytestmark = pytest.mark.slow

DRYNESS_AT_200 = [1.0, 0.9, 0.7, 0.5, 0.3, 0.1]
CASES = {f"X{x}_P200": {"drying.dryness": x, "cell.turgor_kPa": 200} for x in DRYNESS_AT_200}
CASES.update({f"X{x}_P{p}": {"drying.dryness": x, "cell.turgor_kPa": p} for x in (1.0, 0.1) for p in (100, 300)})


@pytest.fixture(scope="module")
def dried(cellsim, root, tmp_path_factory):
    out = tmp_path_factory.mktemp("drying")
    for overrides in CASES.values():
        overrides.update({"compression.steps": 0, "output.snapshot_every": 0})
    paths = run_cases(cellsim, root / "solver" / "examples" / "apple-baseline.json", out, CASES)
    return {name: timeseries(path) for name, path in paths.items()}


def last_window(ts, width_s=5e-6):
    return ts["time_s"] >= ts["time_s"][-1] - width_s


# Known miss, kept visible (strict: it fails loudly once fixed). At the paper's drying L_p the fresh
# cell is still settling at 50 us, ~3.5 kPa below target whatever P_T0 (docs/model-closures.md):
# within 2 % of 200 and 300 kPa, but 3.5 % at 100 kPa.
KNOWN_MISSES = {"X1.0_P100": "fresh cell at 100 kPa: still settling at 50 us, ~3.5 kPa (3.5 %) below target"}


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.xfail(reason=KNOWN_MISSES[n], strict=True))
                                  if n in KNOWN_MISSES else n for n in sorted(CASES)])
def test_drying_reaches_steady_state_on_target_turgor(dried, name):
    ts = dried[name]
    case = ts["case"]
    window = last_window(ts)
    volume = ts["volume_m3"][window]
    assert np.ptp(volume) / volume[-1] < 0.005, "volume still changing over the last 5 us"
    p0_Pa = case["cell"]["turgor_kPa"] * 1e3
    target_Pa = p0_Pa * case["drying"]["dryness"]
    worst = np.max(np.abs(ts["mean_pressure_Pa"][window] - target_Pa))
    assert worst <= 0.02 * p0_Pa, f"mean pressure off its target {target_Pa:.0f} Pa by {worst:.0f} Pa"


def test_fresh_grows_slightly_and_drier_cells_are_smaller(dried):
    final_volume_ratio = [dried[f"X{x}_P200"]["volume_m3"][-1] / dried[f"X{x}_P200"]["volume_m3"][0]
                          for x in DRYNESS_AT_200]
    assert 1.0 < final_volume_ratio[0] < 1.05, "the fresh cell should end slightly larger than it started"
    assert all(v < 1.0 for v in final_volume_ratio[1:])
    assert all(a > b for a, b in zip(final_volume_ratio, final_volume_ratio[1:])), final_volume_ratio


def test_fresh_cell_satisfies_young_laplace(dried):
    ts = dried["X1.0_P200"]
    radius = (3 * ts["volume_m3"][-1] / (4 * np.pi)) ** (1 / 3)
    laplace_Pa = 2 * ts["wall_tension_N_m"][-1] / radius
    assert ts["mean_pressure_Pa"][-1] == pytest.approx(laplace_Pa, rel=0.10)
    # Independent of the closure's own target: the wall tension balances the LJ push it carries.
    assert ts["wall_pressure_Pa"][-1] == pytest.approx(laplace_Pa, rel=0.10)
