"""The analysis of the paper's extensions on synthetic series: a loop's branches and numbers
(analysis/aggregate.py), an ensemble's band, table and claims (analysis/ensembles.py), and a band figure
that names its members' axis (analysis/matrix.py)."""
import numpy as np
import pandas as pd
import pytest
import yaml

from analysis import aggregate, ensembles, matrix


def loop_series(peak=0.15, set_=0.04, n=200):
    """A compression that loads to `peak` and unloads to `set_`: plate down, then up."""
    down = np.linspace(0, peak, n)
    up = np.linspace(peak, set_, n)[1:]
    strain = np.concatenate([down, up])
    stress = np.concatenate([1e6 * down ** 2, 1e6 * peak ** 2 * ((up - set_) / (peak - set_)) ** 3])
    top_z = np.concatenate([100e-6 - 150e-6 * down, 100e-6 - 150e-6 * peak + 0.5 * 150e-6 * (peak - up)])
    work = np.cumsum(np.r_[0, 0.5 * (stress[1:] + stress[:-1]) * np.diff(strain)]) * 1e-12
    return pd.DataFrame({"stage": 1, "nominal_strain": strain, "plate_stress_Pa": stress, "plate_top_z_m": top_z,
                         "plate_work_J": work, "plastic_loss_J": 0.4 * work.max() * (strain > 0.1) * (strain / peak)})


def test_a_loop_splits_at_the_plates_turn_and_gives_its_set_and_dissipation():
    c = loop_series()
    loading, unloading = aggregate.loading_branch(c), aggregate.unloading_branch(c)
    assert len(loading) == 200 and len(unloading) == 199
    assert loading["nominal_strain"].iloc[-1] == pytest.approx(0.15)
    loop = aggregate.load_unload(c)
    assert loop["unload_permanent_set"] == pytest.approx(0.04)
    assert loop["loop_dissipated_nJ"] == pytest.approx(c["plate_work_J"].iloc[-1] * 1e9)
    # The stress at a strain the unloading passes again is the loading's, not a mix of both branches.
    ts = pd.concat([c.assign(stage=0).iloc[:1], c], ignore_index=True)
    assert aggregate.smoothed_stress_at_strain(ts, 0.10) / 1e3 == pytest.approx(1e3 * 0.10 ** 2, rel=0.02)
    # A compression that only loads has no loop.
    plain = c.iloc[:200]
    assert len(aggregate.loading_branch(plain)) == 200 and np.isnan(aggregate.load_unload(plain)["unload_permanent_set"])


def test_a_band_is_the_mean_and_percentiles_of_its_members_on_their_shared_range():
    x = np.linspace(0, 0.2, 50)
    members = [(x * s, 100 * x * s * k) for k, s in zip(range(1, 11), np.linspace(0.9, 1.0, 10))]
    grid, mean, low, high = ensembles.band(members)
    assert grid[0] == pytest.approx(0.0) and grid[-1] == pytest.approx(0.2 * 0.9)  # what every member reaches
    assert mean == pytest.approx(100 * grid * 5.5)  # y = 100 k x for member k: the mean of k is 5.5
    assert low == pytest.approx(100 * grid * np.percentile(range(1, 11), 10))
    assert high == pytest.approx(100 * grid * np.percentile(range(1, 11), 90))
    assert np.all(low <= mean) and np.all(mean <= high)
    # The loading branch only, and records that do not advance are dropped.
    rx, ry = ensembles.rising([0, 0.1, 0.1, 0.2, 0.15, 0.05], [0, 1, 1.5, 2, 1, 0])
    assert list(rx) == [0, 0.1, 0.2] and list(ry) == [0, 1, 2]
    assert len(ensembles.band([(np.array([0.0]), np.array([1.0]))])[0]) == 0  # nothing to interpolate


def ensemble_summary():
    rows = []
    for x, scale in ((1.0, 2.0), (0.1, 1.0)):
        for seed in range(1, 9):
            factor = scale * (1 + 0.05 * (seed - 4.5))
            rows.append({"case": f"X{x}_s{seed}", "studies": "ensemble", "dryness": x, "spread": 0.2, "seed": seed,
                         "smoothed_stress_kPa_at_0.05": 100 * factor, "smoothed_stress_kPa_at_0.10": 300 * factor,
                         "peak_force_top_uN": 5000 * factor, "dried_V_over_V0": 1.0 / scale})
    for x, scale in ((1.0, 2.0), (0.1, 1.0)):
        rows.append({"case": f"X{x}", "studies": "ensemble_reference", "dryness": x, "spread": 0, "seed": 1,
                     "smoothed_stress_kPa_at_0.05": 100 * scale, "smoothed_stress_kPa_at_0.10": 300 * scale,
                     "peak_force_top_uN": 5000 * scale, "dried_V_over_V0": 1.0 / scale})
    return pd.DataFrame(rows)


def ensemble_series(summary):
    frames = []
    strain = np.linspace(0, 0.15, 120)
    for _, r in summary.iterrows():
        stress = r["smoothed_stress_kPa_at_0.10"] * 1e3 * (strain / 0.10) ** 2
        frames.append(pd.DataFrame({"case": r["case"], "stage": 1, "nominal_strain": strain, "plate_stress_Pa": stress,
                                    "plate_top_z_m": -strain}))
    return pd.concat(frames, ignore_index=True)


def test_the_ensemble_table_gives_each_ensembles_mean_band_and_the_homogeneous_value():
    config = {"studies": {"ensemble": {"vary": {"dryness": [1.0, 0.1], "spread": [0.2], "seed": list(range(1, 9))}}}}
    summary = ensemble_summary()
    reference = summary[summary["studies"] == "ensemble_reference"]
    table = ensembles.ensemble_table(config, summary, "ensemble", reference)
    assert len(table) == 2 * len(ensembles.ENSEMBLE_QUANTITIES) and set(table["members"]) == {8}
    fresh = table[(table["dryness"] == 1.0) & (table["quantity"] == "stress at 0.10 [kPa]")].iloc[0]
    assert fresh["mean"] == pytest.approx(600) and fresh["homogeneous"] == pytest.approx(600)
    low, high = np.percentile([600 * (1 + 0.05 * (s - 4.5)) for s in range(1, 9)], [10, 90])
    assert fresh["10th-90th"] == f"{low:.4g} to {high:.4g}"
    assert fresh["CV of members"] == pytest.approx(np.std([1 + 0.05 * (s - 4.5) for s in range(1, 9)], ddof=1))


def test_the_claims_are_judged_on_the_ensembles_mean_with_every_members_verdict():
    config = {"studies": {"ensemble": {"vary": {"dryness": [1.0, 0.1], "spread": [0.2], "seed": list(range(1, 9))}}}}
    summary = ensemble_summary()
    reference = summary[summary["studies"] == "ensemble_reference"]
    rows = ensembles.ensemble_claims(config, summary, ensemble_series(summary), "ensemble", reference)
    stiffer, force = rows.iloc[0], rows.iloc[1]
    assert stiffer["value on the mean"] == pytest.approx(2.0, rel=1e-6)  # every fresh member is 2x its dried pair
    assert stiffer["members agreeing"] == "8 of 8" and stiffer["verdict"] == "agree"
    assert stiffer["homogeneous cell"] == pytest.approx(2.0, rel=1e-6)
    assert force["value on the mean"] == pytest.approx(2.0) and force["verdict"] == "agree"


def test_a_band_figure_must_name_an_axis_its_study_varies(root):
    config = yaml.safe_load((root / "config" / "config.yaml").read_text())
    bad = dict(config, figures=dict(config["figures"], ext03=dict(config["figures"]["ext03"], band="turgor_kPa")))
    with pytest.raises(matrix.ConfigError, match=r"figures.ext03.band: 'turgor_kPa' must be an axis"):
        matrix.check(bad, str(root))


def test_the_extensions_page_leaves_out_a_table_whose_study_is_gone():
    from analysis import extensions
    summary = ensemble_summary()
    config = {"studies": {"ensemble": {"vary": {"dryness": [1.0, 0.1], "spread": [0.2], "seed": list(range(1, 9))}},
                          "ensemble_reference": {"vary": {"dryness": [1.0, 0.1]}}}}
    frames = extensions.tables(config, summary, ensemble_series(summary))
    assert frames["load_unload"].empty and frames["band_growth"].empty
    assert len(frames["ensemble"]) == 2 * len(ensembles.ENSEMBLE_QUANTITIES) and len(frames["ensemble_claims"]) == 2
