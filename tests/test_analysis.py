"""The analysis package on its own: matrix expansion, quantities, references, metrics, claims, a figure."""
import pathlib
import re
import subprocess

import numpy as np
import pandas as pd
import pytest
import yaml

from analysis import aggregate, claims, convergence, findings, matrix, quantities, references, tissue
from analysis.figures import common, curves
from conftest import workflow_config


@pytest.fixture(scope="module")
def config(root):
    return yaml.safe_load((root / "config" / "config.yaml").read_text())


def test_matrix_deduplicates_and_shares_dried_states(config):
    cases = matrix.expand(config)
    assert len(matrix.target_cases(config, cases)) == 48  # the paper's studies, the default target
    baseline = cases["D150_G18_P200_t6_v1_X1"]
    assert set(baseline.studies) == {"dryness_turgor", "plate_speed", "shear_modulus", "wall_thickness", "cell_size",
                                     "convergence_resolution", "convergence_time_step", "coupling_comparison",
                                     "ensemble_reference"}
    fast = cases["D150_G18_P200_t6_v10_X0.5"]
    assert fast.dried == cases["D150_G18_P200_t6_v1_X0.5"].dried == "D150_G18_P200_t6_X0.5"
    assert fast.case["compression"]["plate_speed_m_s"] == 10 and fast.case["drying"]["dryness"] == 0.5
    default = {n: cases[n] for n in matrix.target_cases(config, cases)}
    assert len(matrix.dried_states(default)) == 39


def test_hidden_and_keyless_axes_name_what_the_case_runs(config):
    """Resolution levels set only coupled keys; a level's dt shows in the name; the paper's cases
    keep their names (hidden axes at their base value are not named)."""
    cases = matrix.expand(config)
    convergence = matrix.target_cases(config, cases, "convergence")
    # The LJ studies: 3 dryness x (3 levels + pressure at level 1 + dt 0.5 for both) = 18; the ladder and
    # its anchors and sweeps: 32 more (config/config.yaml says which); the closed cells: 19 more
    assert len(convergence) == 69
    closed = cases["D150_dt200_Fcavity_G18_Iadaptive_P200_R2_t6_v1_X1"]  # the closed cell's coupled keys, the level's
    assert closed.case["fluid"]["model"] == "cavity" and closed.case["time"]["scheme"] == "quasi_static"
    assert closed.case["time"]["dt_ns"] == 200 and closed.case["cell"]["n_wall"] == 4134
    assert closed.case["time"]["min_increment_ns"] == 3.125  # the increments axis: adaptive at its snaps
    assert "Cpressure_D150_G18_P200_t6_v1_X0.5" in convergence  # a name: the coupling axis takes names
    ladder = cases["Cpressure_D150_dt0.5_G18_H1.2_P200_R3_t6_v1_X0.1"]  # a single-valued axis fixes a setting
    assert ladder.case["fluid"]["h_over_dx"] == 1.2 and ladder.case["time"]["dt_ns"] == 0.5
    assert ladder.values["smoothing"] == 1.2 and ladder.values["resolution"] == 3
    fine = cases["D150_dt0.5_G18_P200_R3_t6_v1_X0.1"]
    assert fine.case["cell"]["n_fluid"] == 24656 and fine.case["cell"]["n_wall"] == 8268
    assert fine.case["time"]["dt_ns"] == 0.5 and fine.values["dt_ns"] == 0.5 and fine.values["resolution"] == 3
    assert fine.dried == "D150_dt0.5_G18_P200_R3_t6_X0.1"
    assert cases["D150_G18_P200_R2_t6_v1_X1"].case["cell"]["n_fluid"] == 8717
    assert "D150_G18_P200_t6_v1_X1" in convergence  # level 1 at 1 ns is the paper's baseline case
    assert not any("R" in n.split("_")[3] for n in matrix.target_cases(config, cases))


def test_keyless_axis_value_must_be_one_it_defines(config):
    bad = dict(config, studies=dict(config["studies"], extra={"vary": {"resolution": [4]}, "target": "convergence"}))
    with pytest.raises(matrix.ConfigError, match=r"studies.extra.vary.resolution: value 4"):
        matrix.check(bad, ".")


def test_coupled_values_follow_their_axis(config):
    big = matrix.expand(config)["D200_G18_P200_t6_v1_X0.1"]
    set_by_config = {key: big.case["cell"][key] for key in config["base"]["cell"]}
    assert set_by_config == {**config["base"]["cell"], "diameter_um": 200, "n_wall": 2516, "n_fluid": 3708}
    small = matrix.expand(config)["D150_G18_P200_t6_v1_X0.1"]
    assert small.case["cell"]["n_wall"] == 2067


def test_cases_are_complete_so_naming_a_default_in_base_changes_no_case_file(config):
    """Keys the config leaves out take the solver's defaults (derived keys stay out, for the solver to
    derive); base naming a key at its default value (as adding an axis asks) leaves every case file as
    it was."""
    schema = matrix.case_schema()
    case = matrix.expand(config)["D150_G18_P200_t6_v1_X0.1"].case
    for section, spec in schema["properties"].items():
        for key, rule in spec.get("properties", {}).items():
            if "default" in rule:
                assert key in case[section], f"{section}.{key}"
            elif key not in config["base"].get(section, {}):
                assert key not in case.get(section, {}), f"{section}.{key} is derived: the solver fills it"
    assert case["wall"]["bending_stiffness_J"] == 1e-10 and case["coupling"]["model"] == "lennard_jones"
    named = dict(config, base=dict(config["base"], wall={**config["base"]["wall"], "bending_stiffness_J": 1e-10}))
    before, after = matrix.expand(config), matrix.expand(named)
    assert list(before) == list(after)
    assert all(matrix.case_json(before[n].case) == matrix.case_json(after[n].case) for n in before)


def test_names_do_not_depend_on_axis_order(config):
    reordered = dict(config, axes=dict(reversed(list(config["axes"].items()))))
    assert list(matrix.expand(reordered)) == list(matrix.expand(config))


def test_figure_cases_apply_where(config):
    cases = matrix.expand(config)
    assert len(matrix.figure_cases(config, "fig07", cases)) == 6   # 200 kPa, six dryness levels
    assert len(matrix.figure_cases(config, "fig10", cases)) == 6   # two dryness x three turgor
    assert len(matrix.figure_cases(config, "fig11", cases)) == 12  # 3 dryness x 4 speeds


def test_quantities_are_the_solvers_time_series(cellsim):
    table = subprocess.run([cellsim, "outputs"], check=True, capture_output=True, text=True).stdout
    names = {line.split("`/timeseries/")[1].split("`")[0] for line in table.splitlines() if "/timeseries/" in line}
    assert names == set(quantities.QUANTITIES)


def test_reference_reconstruction_honours_published_numbers(config, root):
    strain, stress_kPa = references.load(config["references"]["chakespari_red_delicious"], root)
    assert strain[-1] == pytest.approx(0.312) and stress_kPa[-1] == pytest.approx(370, rel=1e-4)
    initial_slope_MPa = (stress_kPa[1] - stress_kPa[0]) / (strain[1] - strain[0]) / 1e3
    assert initial_slope_MPa == pytest.approx(0.93, rel=0.05)
    assert np.all(np.diff(stress_kPa) > 0)


def test_reference_units_convert(tmp_path):
    (tmp_path / "r.csv").write_text("strain_pct,stress\n5,10\n10,30\n")
    spec = {"file": "r.csv", "strain_unit": "%", "stress_unit": "MPa", "header_rows": 1}
    strain, stress_kPa = references.load(spec, tmp_path)
    assert list(strain) == [0.05, 0.10] and list(stress_kPa) == [1e4, 3e4]


def synthetic_series(stiffness_kPa, name):
    """A compression whose stress is stiffness x strain, after a drying record."""
    strain = np.linspace(0, 0.2, 21)
    rows = {"stage": [0.0] + [1.0] * 21, "nominal_strain": [np.nan] + list(strain),
            "plate_stress_Pa": [np.nan] + list(stiffness_kPa * 1e3 * strain),
            "time_s": np.arange(22) * 1e-6, "plate_force_top_N": [np.nan] + list(stiffness_kPa * strain * 1e-3),
            "volume_m3": [1.0] * 22, "area_m2": [1.0] * 22, "fluid_mass_ratio": [1.0] * 22,
            "mean_pressure_Pa": [2e5] * 22, "wall_pressure_Pa": [2e5] * 22, "wall_strain_mean": [0.001] * 22}
    return pd.DataFrame(rows).assign(case=name)


def test_value_at_strain_interpolates_on_first_crossing():
    ts = synthetic_series(500, "a")
    assert aggregate.value_at_strain(ts, 0.05) == pytest.approx(25e3)
    assert aggregate.value_at_strain(ts, 0.125) == pytest.approx(62.5e3)
    assert np.isnan(aggregate.value_at_strain(ts, 0.5))


def test_energy_verdicts_relate_the_residual_to_what_flowed():
    flows = {name: [0.0, 0.0] for name in aggregate.ENERGY_FLOWS}
    drying = pd.DataFrame({**flows, "drive_energy_J": [0.0, 8.0], "viscous_loss_J": [0.0, 2.0],
                           "energy_residual_J": [0.0, 0.1]})
    compression = drying.iloc[[-1, -1]].reset_index(drop=True).assign(
        plate_work_J=[0.0, 5.0], viscous_loss_J=[2.0, 2.5], damping_loss_J=[0.0, 1.0], energy_residual_J=[0.1, 0.2])
    out = aggregate.energy_account(drying, compression)
    assert out["drying_energy_residual_over_flow"] == pytest.approx(0.1 / 10.0)  # |drive| + |viscous|
    assert out["compression_plate_work_nJ"] == pytest.approx(5e9)
    assert out["compression_energy_residual_over_work"] == pytest.approx(0.1 / 5.0)
    assert out["compression_viscous_loss_over_work"] == pytest.approx(0.5 / 5.0)
    assert out["compression_damping_loss_over_work"] == pytest.approx(1.0 / 5.0)
    assert "compression_plate_work_nJ" not in aggregate.energy_account(drying, compression.iloc[:0])
    assert aggregate.energy_account(drying.drop(columns="energy_residual_J"), compression) == {}


def test_claims_compare_fresh_and_dried(config):
    base = {axis: matrix.base_value(config, axis) for axis in config["axes"]}
    rows, series = [], []
    for dryness, stiffness in [(1.0, 900.0), (0.1, 400.0)]:
        values = dict(base, dryness=dryness)
        ts = synthetic_series(stiffness, f"X{dryness}").assign(section_stress_Pa=np.nan)
        series.append(ts)
        rows.append({**values, "case": f"X{dryness}", "settle_volume_ratio": 1.003 if dryness == 1.0 else 1.001,
                     **aggregate.summarise(ts)})
    verdicts = {r["claim"]: r for r in claims.evaluate(pd.DataFrame(rows), base, pd.concat(series))}
    # The fresh cell's swelling is its inflation by the turgor at rest, not a change during drying.
    assert verdicts["During drying the fresh cell swells slightly and dried cells shrink"]["value"] == 1.003
    stiffer = verdicts["Fresh cells are stiffer than extremely dried ones (X/X0 = 1.0 vs 0.1, 200 kPa)"]
    assert stiffer["value"] == pytest.approx(900 / 400) and stiffer["verdict"] == "agree"  # curves, linear
    assert stiffer["point_value"] == pytest.approx(900 / 400)
    assert verdicts["G = 18 and 0.18 MPa give virtually overlapping curves"]["verdict"] == "not run"


def test_a_claim_on_curves_that_stop_short_is_not_reached_and_one_without_its_cases_not_run(config):
    """X/X0 = 0.1 against 0.3 from strain 0.1 on: compressions that end at strain 0.08 (a reduced config's
    end strain) are 'not reached'; without the X/X0 = 0.3 case the claim is 'not run'."""
    base = {axis: matrix.base_value(config, axis) for axis in config["axes"]}
    claim = "X/X0 = 0.1 stays above X/X0 = 0.3 at strains above 0.1"

    def verdict(cases, end_strain):
        rows, series = [], []
        for dryness, stiffness in cases:
            ts = synthetic_series(stiffness, f"X{dryness}").assign(section_stress_Pa=np.nan)
            ts = ts[~(ts["nominal_strain"] > end_strain)]
            series.append(ts)
            rows.append({**base, "dryness": dryness, "case": f"X{dryness}", **aggregate.summarise(ts)})
        verdicts = {r["claim"]: r for r in claims.evaluate(pd.DataFrame(rows), base, pd.concat(series))}
        return verdicts[claim]["verdict"]

    assert verdict([(0.1, 500.0), (0.3, 400.0)], 0.2) == "agree"
    assert verdict([(0.1, 500.0), (0.3, 400.0)], 0.08) == "not reached"
    assert verdict([(0.1, 500.0)], 0.2) == "not run"


def test_curve_verdicts_ignore_one_wiggle_that_decides_a_point_value():
    """Two compressions alike but for one spike at strain 0.05 (a wall particle entering the plate's
    range): the point value sees 27 %, the smoothed curves a few %."""
    strain = np.linspace(0, 0.2, 201)
    stress = 5e5 * strain + 2e4 * np.sin(40 * strain)
    a = pd.DataFrame({"case": "a", "stage": 1.0, "nominal_strain": strain, "plate_stress_Pa": stress})
    spiked = stress.copy()
    spiked[50] *= 1.27
    b = a.assign(case="b", plate_stress_Pa=spiked)
    series = pd.concat([a, b])
    assert aggregate.value_at_strain(b, 0.05) / aggregate.value_at_strain(a, 0.05) == pytest.approx(1.27)
    curve_a, curve_b = claims.stress_curve(series, "a"), claims.stress_curve(series, "b")
    assert claims.relative_rms(curve_a, curve_b) < 0.02
    assert claims.mean_ratio(curve_a, curve_b) == pytest.approx(1.0, abs=0.01)
    assert claims.mean_ratio(curve_a, claims.stress_curve(series.assign(plate_stress_Pa=2 * series["plate_stress_Pa"]), "a")) \
        == pytest.approx(0.5)
    grid, smooth = curve_a
    assert grid[0] == pytest.approx(claims.START_STRAIN) and grid[-1] <= 0.2 - claims.SMOOTH_STRAIN + 1e-9


def test_curves_figure_draws_one_line_per_case_and_the_references(config, root):
    series = pd.concat([synthetic_series(900, "a").assign(dryness=1.0, turgor_kPa=200.0),
                        synthetic_series(400, "b").assign(dryness=0.1, turgor_kPa=200.0)])
    figure = curves.draw(config, "fig07", series, root)
    lines = figure.axes[0].get_lines()
    labels = [line.get_label() for line in lines]
    assert "X/X0 = 1" in labels and "X/X0 = 0.1" in labels
    assert sum("reconstructed" in label for label in labels) == 2
    simulated = next(line for line in lines if line.get_label() == "X/X0 = 1")
    assert simulated.get_ydata()[-1] == pytest.approx(900 * 0.2)  # kPa


def test_report_warns_of_every_case_whose_drying_hit_its_cap():
    import pandas as pd
    from analysis.html_page import warnings_box
    summary = pd.DataFrame({"case": ["A", "B", "C"],
                            "warning": ["", "drying reached drying.steps without a steady state", ""]})
    box = warnings_box(summary)
    assert "1 of 3 cases" in box and "<code>B</code>" in box and "<code>A</code>" not in box
    assert warnings_box(summary.assign(warning="")) == ""
    # A compression stopped at its cap is a note of its own, not the drying's warning.
    capped = "compression reached compression.steps = 25000 at nominal strain 0.148 before compression.end_strain = 0.2"
    box = warnings_box(summary.assign(warning=["", f"drying reached drying.steps without a steady state; {capped}",
                                               capped]))
    drying_box, note = box.split("<details>")
    assert "1 of 3 cases" in drying_box and "<code>C</code>" not in drying_box and "compression reached" not in drying_box
    assert "2 of 3 compressions stopped at their cap" in note and "<code>B</code>" in note and "0.148" in note
    # An energy account left open (the solver's tolerance) is a box of its own, neither the drying's nor the cap's.
    open_account = "energy account: drying's residual is 3.7 % of the energy that flowed (tolerance 2 %)"
    box = warnings_box(summary.assign(warning=["", f"{open_account}; {capped}", ""]))
    assert "1 of 3 cases leave their energy account open" in box and "3.7 %" in box.split("<details>")[0]
    assert "did not reach steady state" not in box and "1 of 3 compressions stopped at their cap" in box


def test_report_warns_of_every_compression_whose_energy_account_does_not_close():
    from analysis.html_page import energy_box
    summary = pd.DataFrame({"case": ["A", "B", "C"], "compression_energy_residual_over_work": [0.01, 4.79, -0.06]})
    box = energy_box(summary)
    assert "1 of 3 compressions" in box and "<code>B</code>" in box and "+479 %" in box
    assert "<code>A</code>" not in box and "<code>C</code>" not in box
    assert energy_box(summary.assign(compression_energy_residual_over_work=0.0)) == ""


def test_run_summary_reads_a_result_files_start_and_steady_state(cellsim, tmp_path):
    from analysis.results import run_summary
    out = tmp_path / "run.h5"
    (tmp_path / "case.json").write_text('{"cell": {"n_wall": 402, "n_fluid": 400}, '
                                        '"coupling": {"repulsion_f0_N_m": 1.5e-11}, '  # coarse cells: config/ci.yaml
                                        '"drying": {"steps": 300}, "compression": {"steps": 0}}')
    subprocess.run([cellsim, "run", str(tmp_path / "case.json"), "-o", str(out), "--quiet"], check=True)
    summary = run_summary(out)
    assert summary["settle_iterations"] > 0
    assert summary["compression_at_cap"] is False  # no compression ran
    assert summary["drying_steady"] is False and summary["drying_steady_time_us"] != summary["drying_steady_time_us"]
    assert summary["warning"] == "drying reached drying.steps without a steady state"  # a str, not bytes


def test_compression_time_and_mass_lost_count_from_the_end_of_drying():
    from analysis.aggregate import with_compression_series
    ts = pd.DataFrame({"time_s": [0.0, 20e-6, 40e-6, 40.1e-6, 41e-6], "stage": [0, 0, 0, 1, 1],
                       "fluid_mass_kg": [2.0, 1.5, 1.0, 0.99, 0.9]})
    out = with_compression_series(ts)
    assert np.isnan(out["compression_time_s"].to_numpy()[:3]).all()
    assert out["compression_time_s"].to_numpy()[3:] == pytest.approx([0.1e-6, 1e-6])
    assert np.isnan(out["compression_mass_lost"].to_numpy()[:3]).all()
    assert out["compression_mass_lost"].to_numpy()[3:] == pytest.approx([0.01, 0.1])


def convergence_summary(stress_of_spacing, dryness=(1.0,), levels=((3082, 2067, 1.0), (8717, 4134, 1.0), (24656, 8268, 0.5))):
    """A summary table of the resolution study with stresses f(h) at the levels' spacings h."""
    rows = []
    for x in dryness:
        for level, (n_fluid, n_wall, dt) in enumerate(levels, start=1):
            h = n_fluid ** (-1 / 3)
            rows.append({"case": f"R{level}_X{x}", "studies": "convergence_resolution", "dryness": x,
                         "resolution": level, "coupling": "lennard_jones", "cell.n_fluid": n_fluid,
                         "cell.n_wall": n_wall, "time.dt_ns": dt, "smoothed_stress_kPa_at_0.05": stress_of_spacing(h),
                         "smoothed_stress_kPa_at_0.10": 2 * stress_of_spacing(h), "peak_force_top_uN": 1.0,
                         "dried_V_over_V0": 1.0, "load_F_over_pA": 2.0, "load_fluid_share": 0.5})
    return pd.DataFrame(rows)


def test_convergence_table_gives_changes_and_the_observed_order(config):
    # f = 100 + 5e3 h^2: second order; the changes shrink by the spacing ratio squared (2).
    summary = convergence_summary(lambda h: 100 + 5e3 * h ** 2)
    table = convergence.study_table(config, "convergence_resolution", summary)
    assert list(table["resolution"]) == [1, 2, 3]
    f = [100 + 5e3 * n ** (-2 / 3) for n in (3082, 8717, 24656)]
    assert table["change_smoothed_stress_kPa_at_0.05"].iloc[2] == pytest.approx((f[2] - f[1]) / f[1])
    assert table["order_smoothed_stress_kPa_at_0.05"].iloc[2] == pytest.approx(2.0, rel=1e-3)  # the two spacing ratios differ by 1e-5
    verdict = convergence.verdicts(config, table)
    assert list(verdict["converged"]) == ["yes"]  # 100 + 5e3 h^2 changes by < 1 % between the finest two


def test_convergence_page_shows_verdicts_tables_and_figures(config, tmp_path):
    summary = convergence_summary(lambda h: 100 + 5e3 * h ** 2, dryness=(1.0, 0.1))
    table = convergence.study_table(config, "convergence_resolution", summary)
    (tmp_path / "report").mkdir()
    convergence.write_page(tmp_path / "report" / "convergence.html", config, table,
                           {"conv01": str(tmp_path / "figures" / "conv01.png")}, {"coupling_comparison": summary.head(2)})
    page = (tmp_path / "report" / "convergence.html").read_text()
    for text in ("Verdicts", "Resolution convergence", "The two wall-fluid couplings", "../figures/conv01.png",
                 "<td>yes</td>", "stress at strain 0.05 [kPa]"):
        assert text in page, text


def test_convergence_verdicts_say_no_and_incomplete(config):
    oscillating = convergence_summary(lambda h: 100 * (1.2 if h < 0.04 else 1.0))  # jumps 20 % at level 3
    assert list(convergence.verdicts(config, convergence.study_table(config, "convergence_resolution",
                                                                     oscillating))["converged"]) == ["no"]
    two_levels = convergence_summary(lambda h: 100.0, levels=((3082, 2067, 1.0), (8717, 4134, 1.0)))
    table = convergence.study_table(config, "convergence_resolution", two_levels)
    assert list(convergence.verdicts(config, table)["converged"]) == ["incomplete"]
    assert np.isnan(convergence.observed_order(100, 110, 99, 1.41, 1.41))  # no monotone shrinking: no order


def test_convergence_verdict_names_the_metric_past_its_limit(config):
    """F / (p A_c) must hold to 5 %, the stresses to 10 %: a load partition moving 8 % fails alone."""
    summary = convergence_summary(lambda h: 100.0)
    summary["load_F_over_pA"] = [2.0, 2.0, 2.16]
    verdict = convergence.verdicts(config, convergence.study_table(config, "convergence_resolution", summary))
    assert list(verdict["converged"]) == ["no"]
    assert verdict["between the two finest"].iloc[0] == "F / (p A_c), strain 0.05-0.15 +8.0 % (limit 5 %)"


def test_a_single_valued_axis_fixes_a_setting_and_a_sweep_has_no_criterion(config):
    assert convergence.refined_axis(config, "pressure_resolution") == "resolution"  # smoothing, dt: one value each
    assert convergence.refined_axis(config, "bulk_modulus") == "K_MPa"
    rows = [{"case": f"K{k}", "studies": "bulk_modulus", "dryness": 1.0, "coupling": "pressure", "K_MPa": k,
             "cell.n_fluid": 3082, "cell.n_wall": 2067, "time.dt_ns": 0.5, "smoothed_stress_kPa_at_0.05": 50.0,
             "smoothed_stress_kPa_at_0.10": 300 - 2000 / k, "peak_force_top_uN": 1.0, "dried_V_over_V0": 1.0,
             "load_F_over_pA": 2.0, "load_fluid_share": 0.5} for k in (10, 20, 40, 80)]
    table = convergence.study_table(config, "bulk_modulus", pd.DataFrame(rows))
    assert list(table["K_MPa"]) == [10, 20, 40, 80]
    assert list(convergence.verdicts(config, table)["converged"]) == [""]  # a sweep: no criterion
    note = convergence.bulk_modulus_note(table)[0]  # stress = s + a/K through the two stiffest: s = 300
    assert "s = 300 kPa" in note and "(the paper's 20 MPa: -33 %)" in note


def test_anchor_runs_are_the_anchor_studies_and_the_ladders_fresh_cells(config):
    runs = convergence.anchor_runs(config, matrix.expand(config))
    kinds = {kind: sorted(level for k, _, level in runs if k == kind) for kind in ("breathing", "laplace", "membrane")}
    assert kinds == {"breathing": [1, 2, 3], "laplace": [1, 1, 2, 2, 3], "membrane": [1, 2, 3]}
    assert all("kwc0" in case and "v0.25" in case for kind, case, _ in runs if kind == "membrane")


def test_tissue_target_runs_closed_cell_slabs_beside_their_cells_and_the_bounds_that_fit(config):
    cases = matrix.expand(config)
    tissue_cases = matrix.target_cases(config, cases, "tissue")
    # 12 slabs, 6 single cells (3 dryness x sealed and drained), and each bound's fresh slab and cell.
    assert len(tissue_cases) == 12 + 6 + 2 + 2 + 2
    assert all(cases[n].case["fluid"]["model"] == "cavity" and cases[n].case["time"]["scheme"] == "dynamic"
               and cases[n].case["compression"]["plate_speed_m_s"] == 1 for n in tissue_cases)
    assert not set(tissue_cases) & set(matrix.target_cases(config, cases))  # none of the default target's
    water = [cases[n] for n in tissue_cases if "tissue_water" in cases[n].studies]
    assert {c.case["time"]["dt_ns"] for c in water} == {0.5}  # Eq 11's transfer time at 2.2 GPa: 0.65 ns
    assert matrix.target_figures(config, "tissue") == [f"tis{i:02d}" for i in range(1, 8)]
    for target in ("tissue", "tissue_bounds", "tissue_clusters", "tissue_check", "tissue_large"):
        assert not set(matrix.target_figures(config, target)) & set(matrix.target_figures(config))


def test_the_tissue_targets_beyond_the_hour_hold_the_quasi_static_limit_the_clusters_the_check_and_large_slabs(config):
    cases = matrix.expand(config)
    bounds = [cases[n] for n in matrix.target_cases(config, cases, "tissue_bounds")]
    assert len(bounds) == 4 and {c.case["time"]["scheme"] for c in bounds} == {"quasi_static"}
    clusters = [cases[n] for n in matrix.target_cases(config, cases, "tissue_clusters")]
    assert {c.case["tissue"]["cells_x"] ** 3 for c in clusters} == {1, 8, 27}
    check = [cases[n] for n in matrix.target_cases(config, cases, "tissue_check")]
    assert sorted((c.case["fluid"]["model"], c.case["time"]["scheme"]) for c in check) == [
        ("cavity", "dynamic"), ("cavity", "quasi_static"), ("sph", "dynamic")]
    large = [cases[n] for n in matrix.target_cases(config, cases, "tissue_large")]
    tissue = large[0].case["tissue"]
    assert len(large) == 12 and tissue["cells_x"] * tissue["cells_y"] >= 12 and tissue["cells_z"] == 5
    assert tissue["packing"] == "close" and tissue["cells_y"] % 2 == 0 and tissue["diameter_spread"] == 0.1


def test_slab_cases_are_periodic_and_confined_and_unconfined_share_one_drying(config):
    cases = matrix.expand(config)
    slabs = [c for c in cases.values() if "tissue" in c.studies]
    assert len(slabs) == 12 and all(c.case["tissue"]["lateral"] == "periodic" for c in slabs)
    assert {c.case["compression"]["lateral"] for c in slabs} == {"confined", "unconfined"}
    assert {c.case["compression"]["Lp_m_per_s_Pa"] for c in slabs} == {1e-12, 1e-6}
    assert len({c.dried for c in slabs}) == 3  # one drying per dryness serves both sides and both L_p


def test_a_figure_may_draw_several_studies_of_one_target_only(config):
    cases = matrix.expand(config)
    drawn = matrix.figure_cases(config, "tis07", cases)
    assert {s for n in drawn for s in cases[n].studies} >= {"tissue", "tissue_cell", "tissue_thick_wall",
                                                         "tissue_level2", "tissue_water"}
    assert len(drawn) == 8  # the fresh confined closed slab and cell, and each bound's two
    bad = dict(config, figures=dict(config["figures"], tis01=dict(config["figures"]["tis01"], study=["tissue", "plate_speed"])))
    with pytest.raises(matrix.ConfigError, match=r"figures.tis01.study: its studies .* belong to different targets"):
        matrix.check(bad, ".")
    bad = dict(config, figures=dict(config["figures"], tis04=dict(config["figures"]["tis04"], y=["plate_stress_Pa"])))
    with pytest.raises(matrix.ConfigError, match=r"figures.tis04: a modulus figure needs lines and y among"):
        matrix.check(bad, ".")


def test_shrinkage_figure_needs_known_references_and_a_study_that_dries(config):
    bad = dict(config, figures=dict(config["figures"], tis06=dict(config["figures"]["tis06"],
                                                                 shrinkage_references=["nonesuch"])))
    with pytest.raises(matrix.ConfigError, match=r"figures.tis06.shrinkage_references: unknown reference 'nonesuch'"):
        matrix.check(bad, ".")


def test_shrinkage_figure_draws_cells_tissues_and_reference_lines(config, root):
    from analysis.figures import shrinkage
    rows = []
    for cells in (1, 8):
        for x in (1.0, 0.5, 0.1):
            tissue_v = 0.35 + 0.6 * x if cells > 1 else np.nan
            rows.append({"cells": cells, "dryness": x, "dried_V_over_V0": 0.3 + 0.7 * x,
                         "dried_tissue_V_over_V0": tissue_v})
    figure = shrinkage.draw(config, "tis06", pd.DataFrame(rows), root)
    ax = figure.axes[0]
    labels = [line.get_label() for line in ax.get_lines()]
    assert labels[:3] == ["cells = 8: tissue (hull of its walls)", "cells = 8: its cells' own volumes", "cells = 1"]
    assert len(ax.get_lines()) == 3 + len(config["figures"]["tis06"]["shrinkage_references"])
    tissue_line = ax.get_lines()[0]
    assert list(tissue_line.get_ydata()) == pytest.approx([0.35 + 0.6 * x for x in (0.1, 0.5, 1.0)])
    ideal = [line for line in ax.get_lines() if line.get_label().startswith("volume lost")][0]
    assert list(ideal.get_xdata()) == [0, 1] and list(ideal.get_ydata()) == pytest.approx([0.1, 1.0])


def test_table_cells_print_counts_in_full_and_measures_to_four_digits():
    from analysis.html_page import cell_text
    assert cell_text(13824.0) == "13824"  # a bond count, not 1.382e+04
    assert cell_text(10690.4) == "10690"  # a peak force in uN, not 1.069e+04
    assert cell_text(-12345.6) == "-12346"
    assert cell_text(0.52604) == "0.526"
    assert cell_text(189.5029) == "189.5"
    assert cell_text(float("nan")) == ""
    assert cell_text("a<b") == "a&lt;b"


def test_figures_are_saved_the_same_bytes_every_time(tmp_path):
    """No creation date in the PDF: a figure redrawn from the same data is the same file."""
    saved = []
    for k in range(2):
        figure, axes = common.plt.subplots()
        axes.plot([0, 1], [0, 1])
        png, pdf = tmp_path / f"f{k}.png", tmp_path / f"f{k}.pdf"
        common.save(figure, png, pdf)
        saved.append((png.read_bytes(), pdf.read_bytes()))
    assert b"CreationDate" not in saved[0][1]
    assert saved[0] == saved[1]


def test_cell_strain_is_the_gauge_of_a_tissue_and_the_nominal_strain_of_one_cell():
    from analysis.aggregate import with_compression_series
    base = {"time_s": [0.0, 1e-6, 2e-6, 3e-6], "stage": [0, 0, 1, 1], "fluid_mass_kg": [1.0] * 4,
            "nominal_strain": [np.nan, np.nan, 0.02, 0.06]}
    tissue = with_compression_series(pd.DataFrame({**base, "gauge_strain": [np.nan, np.nan, 0.01, 0.04]}))
    cell = with_compression_series(pd.DataFrame({**base, "gauge_strain": [np.nan] * 4}))
    assert np.isnan(tissue["cell_strain"].to_numpy()[:2]).all()
    assert tissue["cell_strain"].to_numpy()[2:] == pytest.approx([0.01, 0.04])
    assert cell["cell_strain"].to_numpy()[2:] == pytest.approx([0.02, 0.06])


def test_apparent_modulus_is_the_slope_over_the_window_and_nan_short_of_its_end():
    from analysis.aggregate import apparent_modulus
    strain = np.linspace(0.0, 0.08, 81)
    # 2 MPa inside the window; a toe below it and a steeper branch above it must not enter the fit.
    stress = np.where(strain < 0.01, 0.5e6 * strain, 2e6 * strain - 0.015e6)
    stress = np.where(strain > 0.05, stress + 5e6 * (strain - 0.05), stress)
    c = pd.DataFrame({"nominal_strain": strain, "footprint_stress_Pa": stress})
    assert apparent_modulus(c, "nominal_strain") == pytest.approx(2e6, rel=1e-9)
    assert np.isnan(apparent_modulus(c[c["nominal_strain"] < 0.04], "nominal_strain"))
    assert np.isnan(apparent_modulus(c, "gauge_strain"))  # a run without the column


def test_reference_curves_fitted_like_the_runs_give_moduli_near_their_initial_tangents(config, root):
    from analysis.figures.modulus import reference_modulus_MPa
    # The reconstructions' initial tangent moduli are 0.93 (Red) and 0.81 MPa (Golden Delicious); over
    # strains 0.01-0.05 their cubics bend by at most an eighth of that.
    for name, initial in (("chakespari_red_delicious", 0.93), ("chakespari_golden_delicious", 0.81)):
        assert reference_modulus_MPa(config, name, root) == pytest.approx(initial, rel=0.15)


def test_modulus_table_has_a_row_per_tissue_kind_and_a_column_per_dryness():
    from analysis.tissue import modulus_table
    rows = []
    for cells, sides in ((1, "free"), (16, "confined"), (16, "unconfined")):
        for x in (1.0, 0.5, 0.1):
            rows.append({"numerics": "pressure coupling, h0/dx 1.2", "cells": cells, "sides": sides,
                         "plate [m/s]": 1.0, "compression L_p": 1e-12, "X/X0": x, "modulus, nominal [MPa]": cells * x,
                         "modulus, gauge [MPa]": 2 * cells * x})
    rows.append(dict(rows[-1], **{"modulus, nominal [MPa]": np.nan}))  # a run short of strain 0.05: left out
    table = modulus_table(pd.DataFrame(rows))
    assert list(table.columns) == ["numerics", "cells", "sides", "plate [m/s]", "compression L_p", "X/X0 = 1",
                                   "X/X0 = 0.5", "X/X0 = 0.1"]
    assert len(table) == 3
    slab = table[(table["cells"] == 16) & (table["sides"] == "unconfined")].iloc[0]
    assert slab["X/X0 = 0.5"] == "8.00 / 16.00"


def test_conjecture_is_answered_from_the_slabs_beside_their_single_cell(tmp_path):
    from analysis.tissue import apple_stress_kPa, conjecture_answer, conjecture_table
    (tmp_path / "apple.csv").write_text("strain,stress\n0,0\n0.2,200\n")  # 1 MPa, linear
    config = {"references": {"apple": {"file": "apple.csv", "header_rows": 1, "strain_unit": "1",
                                       "stress_unit": "kPa", "label": "apple"}}}
    apple = apple_stress_kPa(config, ["apple"], tmp_path)
    assert apple == {"apple": pytest.approx([50.0, 100.0])}
    base = {"numerics": "pressure coupling, h0/dx 1.2", "plate [m/s]": 1.0, "X/X0": 1.0}
    rows = [dict(base, cells=1, sides="free", **{"compression L_p": 1e-12, "x single cell at 0.05": np.nan}),
            dict(base, cells=8, sides="free", **{"compression L_p": 1e-12, "x single cell at 0.05": 2.0}),
            dict(base, cells=16, sides="confined", **{"compression L_p": 1e-12, "x single cell at 0.05": 4.0,
                 "x single cell at 0.10": 5.0, "modulus x single cell": 6.0, "stress at 0.05 [kPa]": 500.0,
                 "stress at 0.10 [kPa]": 2000.0}),
            dict(base, cells=16, sides="unconfined", **{"compression L_p": 1e-6, "x single cell at 0.05": 0.5,
                 "x single cell at 0.10": 2.0, "modulus x single cell": 0.25, "stress at 0.05 [kPa]": 100.0,
                 "stress at 0.10 [kPa]": 300.0}),
            dict(base, cells=16, sides="confined", **{"X/X0": 0.5, "compression L_p": 1e-6,
                 "x single cell at 0.05": 0.8, "x single cell at 0.10": 0.9, "modulus x single cell": np.nan,
                 "stress at 0.05 [kPa]": 10.0, "stress at 0.10 [kPa]": 20.0}),
            # a slab at a plate speed no single cell ran at: no ratio, not compared
            dict(base, cells=16, sides="confined", **{"plate [m/s]": 4.0, "compression L_p": 1e-12,
                 "x single cell at 0.05": np.nan})]
    compared = conjecture_table(pd.DataFrame(rows), apple)
    assert list(compared["sides"]) == ["confined", "unconfined", "confined"]
    assert list(compared["drainage"]) == ["sealed", "drained", "drained"]
    assert list(compared["x apple at 0.05"]) == ["10.0-10.0", "2.0-2.0", "-"]  # fresh cells only
    assert list(compared["x apple at 0.10"]) == ["20.0-20.0", "3.0-3.0", "-"]
    answer = conjecture_answer(compared)
    assert "Of 3 periodic slabs" in answer
    assert "at nominal strain 0.05, 2 of 3 carry less stress than their cell (0.50-4.00 times its stress)" in answer
    assert "at nominal strain 0.10, 1 of 3 carry less stress than their cell (0.90-5.00 times its stress)" in answer
    assert "over the interior strain, 1 of 2 have a lower modulus (0.25-6.00 times the cell's)" in answer
    assert "not answered" in conjecture_answer(conjecture_table(pd.DataFrame(rows[:2]), apple))
    one = conjecture_answer(conjecture_table(pd.DataFrame(rows[:3]), apple))
    assert "Of 1 periodic slab beside" in one and "(4.00 times its stress)" in one


def test_a_tissue_meets_the_single_cell_of_its_own_numerics_and_the_page_names_them():
    from analysis.tissue import numerics, single_cell_of
    base = {"fluid.model": "cavity", "time.scheme": "dynamic", "coupling.model": "lennard_jones",
            "fluid.h_over_dx": 0.888, "cell.n_wall": 2067, "wall.bending_stiffness_J": 1e-10,
            "fluid.bulk_modulus_MPa": 20.0, "dryness": 1.0, "compression.plate_speed_m_s": 1.0,
            "compression.Lp_m_per_s_Pa": 1e-12}
    rows = pd.DataFrame([dict(base, cells=1, case="cell"),
                         dict(base, cells=1, case="thick cell", **{"wall.bending_stiffness_J": 5.3e-9}),
                         dict(base, cells=1, case="level 2 cell", **{"cell.n_wall": 4134}),
                         dict(base, cells=1, case="quasi-static cell", **{"time.scheme": "quasi_static"}),
                         dict(base, cells=16, case="thick slab", **{"wall.bending_stiffness_J": 5.3e-9}),
                         dict(base, cells=16, case="water slab", **{"fluid.bulk_modulus_MPa": 2200.0})])
    assert numerics(rows.iloc[0]) == "closed cells, dynamic, level 1"
    assert numerics(rows.iloc[4]) == "closed cells, dynamic, level 1, k_b 5.3e-09 J"  # 5.3e-9 is not 1e-10
    assert numerics(rows.iloc[3]) == "closed cells, quasi-static, level 1"
    assert numerics(dict(base, **{"fluid.model": "sph", "coupling.model": "pressure", "fluid.h_over_dx": 1.2})) \
        == "SPH, pressure coupling, h0/dx 1.2, level 1"
    assert single_cell_of(rows, rows.iloc[4])["case"] == "thick cell"
    assert single_cell_of(rows, rows.iloc[5]) is None  # no single cell at water's K ran


def test_the_check_table_sets_each_fluid_beside_the_sph_slab_and_the_paragraph_quotes_the_tables():
    from analysis.tissue import check_table, conjecture_paragraph
    base = {"cells": 16, "sides": "confined", "compression L_p": 1e-12, "X/X0": 1.0, "plate [m/s]": 1.0,
            "stress at 0.05 [kPa]": 600.0, "stress at 0.10 [kPa]": 2000.0, "modulus, nominal [MPa]": 14.0,
            "modulus, gauge [MPa]": 20.0, "gauge at nominal 0.10": 0.07}
    frame = pd.DataFrame([dict(base, numerics="SPH, pressure coupling, h0/dx 1.2, level 1"),
                          dict(base, numerics="closed cells, dynamic, level 1", **{"stress at 0.05 [kPa]": 582.0}),
                          dict(base, numerics="closed cells, quasi-static, level 1", **{"X/X0": 0.1})])  # no twin
    checked = check_table(frame)
    assert len(checked) == 1 and checked.iloc[0]["stress at 0.05 / SPH's - 1"] == pytest.approx(-0.03)
    assert checked.iloc[0]["modulus, gauge / SPH's - 1"] == pytest.approx(0.0)

    slab = dict(base, numerics="closed cells, dynamic, level 1", **{"x single cell at 0.05": 2.0})
    cell = dict(slab, cells=1, sides="free", **{"modulus, gauge [MPa]": 5.0, "x single cell at 0.05": np.nan})
    drained = dict(slab, sides="unconfined", **{"compression L_p": 1e-6, "modulus, gauge [MPa]": 9.0})
    frame = pd.DataFrame([slab, cell, drained])
    compared = pd.DataFrame([{"x single cell at 0.05": 2.0, "x single cell at 0.10": np.nan,
                              "modulus (gauge) x single cell": 4.0}])
    text = conjecture_paragraph(compared, frame, {"apple": (0.7, 0.9)})
    assert "the slab's modulus over its interior strain is 20.00 MPa" in text and "the single cell's 5.00 MPa" in text
    assert "initial tangent modulus of 0.90-0.90 MPa" in text
    assert "the closest case run here is the fresh slab drained (compression L_p 1e-06), unconfined" in text
    assert "its modulus is 14.00 MPa over the plates' strain (15.6-15.6 times the apple tissue's)" in text
    assert "9.00 MPa over the interior strain (10.0-10.0 times the apple tissue's), whose gauge reads 0.070" in text


def test_a_snapshot_is_picked_by_its_nominal_strain_within_its_tolerance(tmp_path):
    import h5py
    from analysis.results import pick_snapshot
    path = tmp_path / "run.h5"
    with h5py.File(path, "w") as f:
        f.attrs["completed"] = 1
        f["timeseries/time_s"] = np.arange(5.0)
        f["timeseries/nominal_strain"] = np.array([0, 0, 0.04, 0.095, 0.12])
        f["mesh/triangles"], f["mesh/wall_cell"], f["mesh/fluid_cell"] = np.zeros((1, 3), int), [0], [0]
        for k, (time, stage) in enumerate([(1.0, 0), (2.0, 1), (3.0, 1), (4.0, 1)]):
            g = f.create_group(f"snapshots/{k:06d}")
            g.attrs.update({"time_s": time, "stage": stage, "plate_top_z_m": 0.0, "plate_bottom_z_m": 0.0})
            for name in ("wall_positions", "fluid_positions"):
                g[name] = np.full((1, 3), float(k))
            g["fluid_pressure"] = [0.0]
    assert pick_snapshot(path, "strain_0.1")["time_s"] == 3.0   # at strain 0.095
    assert pick_snapshot(path, "strain_0.04")["time_s"] == 2.0
    with pytest.raises(ValueError, match="no compression snapshot near strain 0.3 .the nearest is at 0.120"):
        pick_snapshot(path, "strain_0.3")


def test_a_compression_stopped_at_its_cap_before_its_end_says_so(cellsim, tmp_path):
    """issue 51: a compression that ends at compression.steps before its end_strain says so in the log,
    in the file's warning and in the summary's compression_at_cap; one that reaches it does not."""
    from analysis.results import run_summary
    case = tmp_path / "case.json"
    case.write_text('{"cell": {"n_wall": 162, "n_fluid": 100}, "settle": {"max_iterations": 40}, '
                    '"drying": {"steps": 40}, "compression": {"steps": 300, "plate_speed_m_s": 50}}')
    outcomes = {}
    for end_strain in (0.5, 0.01):
        out = tmp_path / f"to {end_strain}.h5"
        done = subprocess.run([cellsim, "run", str(case), "-o", str(out), "--quiet",
                               "--set", f"compression.end_strain={end_strain}"], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        outcomes[end_strain] = (done.stderr, run_summary(out))
    log, summary = outcomes[0.5]
    assert summary["compression_at_cap"] is True
    # after the start's and the drying's warnings (these stages are cut short too)
    assert "; compression reached compression.steps = 300 at nominal strain " in summary["warning"]
    assert summary["warning"].endswith(" before compression.end_strain = 0.5")
    assert "WARNING: compression reached compression.steps = 300" in log
    log, summary = outcomes[0.01]
    assert summary["compression_at_cap"] is False and "compression reached" not in summary["warning"]
    assert "WARNING: compression" not in log


def test_a_half_written_result_in_a_results_folder_is_named_not_read(small_runs, tmp_path):
    """issue 51: a result file cut short (copied in part, a disk that filled) stops the tables with an
    error that names the file, not with h5py's message, which does not."""
    from analysis.results import IncompleteResult, timeseries
    whole = pathlib.Path(small_runs[1.0][0])
    cut = tmp_path / "cut.h5"
    cut.write_bytes(whole.read_bytes()[: whole.stat().st_size // 2])
    with pytest.raises(IncompleteResult, match=r"cut\.h5: cannot be read as a cellsim result .*truncated file"):
        timeseries(cut)


def test_the_tissue_tables_numerics_label_is_the_cases_own():
    """A pressure-coupling case is labelled with the h0/dx it ran with, not a fixed one."""
    row = {"fluid.model": "sph", "time.scheme": "dynamic", "cell.n_wall": 2067, "wall.bending_stiffness_J": 1e-10,
           "fluid.bulk_modulus_MPa": 20.0}
    assert tissue.numerics(dict(row, **{"coupling.model": "pressure", "fluid.h_over_dx": 1.25})) \
        == "SPH, pressure coupling, h0/dx 1.25, level 1"
    assert tissue.numerics(dict(row, **{"coupling.model": "lennard_jones", "fluid.h_over_dx": 0.888})) \
        == "paper's (LJ), level 1"


def test_a_closed_cells_rows_show_no_coupling_and_no_fluid_particles(config):
    """A cavity cell reads neither the coupling nor cell.n_fluid: its rows say so, and group apart from SPH."""
    summary = convergence_summary(lambda h: 100.0, levels=((3082, 2067, 200.0), (8717, 4134, 200.0)))
    summary["studies"] = "closed_cell_resolution"
    summary["fluid"] = "cavity"
    table = convergence.study_table(config, "closed_cell_resolution", summary)
    assert list(table["coupling"]) == ["-", "-"] and list(table["n_wall"]) == [2067, 4134]
    assert list(convergence.readable(table)["n_fluid"]) == ["-", "-"]  # shown so; the table keeps the count
    assert table["change_smoothed_stress_kPa_at_0.05"].iloc[1] == 0  # still ordered by the level
    verdict = convergence.verdicts(config, table)
    assert list(verdict["fluid"]) == ["cavity"] and list(verdict["converged"]) == ["yes"]
    sph = convergence.study_table(config, "convergence_resolution", convergence_summary(lambda h: 100.0).assign(fluid="sph"))
    assert set(sph["coupling"]) == {"lennard_jones"} and list(convergence.readable(sph)["n_fluid"])[0] == 3082


def test_the_reports_findings_count_this_runs_numbers(root):
    """The report's own findings are this run's: its configuration and how far to trust it, its claims'
    verdicts counted, the base cell's dried volumes and stresses, the energy account's range."""
    config = workflow_config(root, [])
    base = {axis: matrix.base_value(config, axis) for axis in config["axes"] if matrix.base_value(config, axis) is not None}
    rows = [dict(base, dryness=x, dried_V_over_V0=v, compression_energy_residual_over_work=r,
                 **{"smoothed_stress_kPa_at_0.05": s5, "smoothed_stress_kPa_at_0.10": s10})
            for x, v, r, s5, s10 in [(1.0, 1.0, 0.004, 65.5, 122.7), (0.5, 0.517, -0.011, 40.0, 80.0),
                                     (0.1, 0.269, 0.008, 30.0, 55.0)]]
    rows.append(dict(rows[0], turgor_kPa=100, dried_V_over_V0=0.9))  # not the base cell: not quoted
    summary = pd.DataFrame(rows)
    verdicts = [{"verdict": v} for v in ["agree"] * 12 + ["disagree"] * 3 + ["not run"]]
    text = " ".join(findings.this_run(config, summary, verdicts))
    assert "Lennard-Jones coupling, resolution level 1" in text and "depend on the particle count" in text
    assert "The paper's 16 claims: 12 agree, 3 disagree, 1 not run" in text
    assert "V/V0: 0.517 at X/X0 = 0.5, 0.269 at X/X0 = 0.1 (the base cell)" in text
    assert "65.5 kPa at strain 0.05 and 122.7 kPa at strain 0.10" in text
    assert "residual 0.4-1.1 % of the plate work" in text

    converged = yaml.safe_load((root / "config" / "converged.yaml").read_text())
    config = workflow_config(root, ["config/converged.yaml"])
    assert converged["base"]["coupling"]["model"] == "pressure"
    text = " ".join(findings.this_run(config, summary, verdicts))
    assert "pressure coupling, resolution level 2" in text and "hold to 8 % up to strain 0.05" in text and "converged up to" not in text

    config = workflow_config(root, ["config/ci.yaml"])  # reduced cells; their compressions stop at 0.1
    summary["end_strain"] = 0.1
    summary.loc[summary["dryness"] == 1.0, "smoothed_stress_kPa_at_0.10"] = np.nan
    text = " ".join(findings.this_run(config, summary, verdicts))
    assert "reduced cells (642 wall particles, coarser than the paper's level 1)" in text
    assert "65.5 kPa at strain 0.05 (mean" in text and "nan" not in text

    page = findings.section(config, summary, verdicts, root)
    assert page.index("This run") < page.index("What the project's runs found") < page.index("Limitations")


def test_the_pages_name_the_code_that_made_them(root, tmp_path):
    """The version is CMakeLists.txt's; the commit is the checkout's, and a copy outside git says so."""
    from analysis import provenance
    cmake = re.search(r"project\(cellsim VERSION ([\d.]+)", (root / "CMakeLists.txt").read_text()).group(1)
    assert provenance.version(root) == cmake
    assert re.fullmatch(r"[0-9a-f]{12}( \+ changes not committed)?", provenance.commit(root))
    (tmp_path / "CMakeLists.txt").write_text("project(cellsim VERSION 9.8.7 LANGUAGES C CXX)\n")
    assert provenance.line(tmp_path) == "cellsim 9.8.7, commit unknown (not a git checkout)"
