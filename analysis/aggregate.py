"""Tidy tables from the runs: one row per (case, record), and one row per case with summary
metrics. Every case parameter is a column ('cell.turgor_kPa', ...), and so is every axis."""
import numpy as np
import pandas as pd

from analysis.quantities import ENERGY_TERMS
from analysis.results import flatten, resolved_case, run_summary, timeseries

STRAINS = (0.05, 0.10, 0.15)  # nominal strains at which the stress is reported
LOAD_WINDOW = (0.05, 0.15)    # nominal strains over which the load partition is averaged
MODULUS_WINDOW = (0.01, 0.05)  # strains over which the apparent modulus is fitted (Chakespari's initial tangent)


def rows_of(summary, study):
    """The summary's rows of the cases that belong to `study` (its `studies` column lists them)."""
    return summary[summary["studies"].str.split().apply(lambda s: study in s)]


def loading_branch(compression):
    """The compression records up to the top plate's lowest point: all of them, unless the plate turned
    back (compression.unload_at_strain); then the loading, without the unloading at the same strains."""
    if compression.empty or "plate_top_z_m" not in compression:
        return compression
    return compression.iloc[: int(np.argmin(compression["plate_top_z_m"].to_numpy())) + 1]


def unloading_branch(compression):
    """The records after the top plate's lowest point (empty if it never turned back)."""
    if compression.empty or "plate_top_z_m" not in compression:
        return compression.iloc[0:0]
    return compression.iloc[int(np.argmin(compression["plate_top_z_m"].to_numpy())) + 1:]


def value_at_strain(ts, strain, column="plate_stress_Pa"):
    """A series' value (the plate stress unless named) when the nominal strain first reaches `strain` in
    compression, interpolated between records (NaN if never)."""
    c = ts[ts["stage"] == 1]
    e, s = c["nominal_strain"].to_numpy(), c[column].to_numpy()
    above = np.nonzero(e >= strain)[0]
    if len(above) == 0:
        return np.nan
    i = above[0]
    if i == 0:
        return s[0]
    return s[i - 1] + (s[i] - s[i - 1]) * (strain - e[i - 1]) / (e[i] - e[i - 1])


SMOOTH_STRAIN = 0.01  # half-width of the strain window a smoothed stress averages over


def window_mean(strain, values, at, half_width=SMOOTH_STRAIN):
    """Mean of values over the records whose strain lies within +-half_width of `at` (NaN if none)."""
    inside = np.abs(strain - at) <= half_width
    return values[inside].mean() if inside.any() else np.nan


def smoothed_stress_at_strain(ts, strain, stress_column="plate_stress_Pa"):
    """Mean stress of the compression records within +-SMOOTH_STRAIN of `strain`: the stress at that
    strain without the record-to-record ripple of the plate contact (NaN if the strain is not reached
    by a full window). On the loading branch: a loop's unloading passes the same strains."""
    c = loading_branch(ts[ts["stage"] == 1])
    e = c["nominal_strain"].to_numpy()
    if not len(e) or not np.nanmax(e) >= strain + SMOOTH_STRAIN:
        return np.nan
    return window_mean(e, c[stress_column].to_numpy(), strain)


def with_compression_series(ts):
    """Adds, NaN in drying (compression starts at the last drying record, where drying ended):
    compression_time_s, the time since the plates started; compression_mass_lost, the share of the
    fluid's mass at that moment that has left the cell since (Eq 11: the drained bound); cell_strain,
    the strain of the cells away from the plates: a tissue's interior gauge (model.md §10c), a single
    cell's (or a one-layer tissue's) nominal strain, as the plates press it directly."""
    drying = ts["stage"] == 0
    start = ts[drying].iloc[-1] if drying.any() else ts.iloc[0]
    derived = {"compression_time_s": np.where(drying, np.nan, ts["time_s"] - start["time_s"]),
               "compression_mass_lost": np.where(drying, np.nan, 1.0 - ts["fluid_mass_kg"] / start["fluid_mass_kg"])}
    if "nominal_strain" in ts:
        cell_strain = ts["gauge_strain"].fillna(ts["nominal_strain"]) if "gauge_strain" in ts else ts["nominal_strain"]
        derived["cell_strain"] = np.where(drying, np.nan, cell_strain)
    return ts.assign(**derived)


def apparent_modulus(compression, strain_column, stress_column="footprint_stress_Pa", window=MODULUS_WINDOW):
    """The slope [Pa] of stress against strain, fitted by least squares to the loading records whose
    strain lies in `window`: the apparent modulus at small strain (a texture analyser's initial
    tangent). NaN unless the loading reaches the window's end and holds 5 records in it."""
    c = loading_branch(compression)
    if c.empty or strain_column not in c or stress_column not in c:
        return np.nan
    e, s = c[strain_column].to_numpy(), c[stress_column].to_numpy()
    inside = (e >= window[0]) & (e <= window[1]) & np.isfinite(s)
    if not np.nanmax(e, initial=-np.inf) >= window[1] or inside.sum() < 5:
        return np.nan
    return float(np.polyfit(e[inside], s[inside], 1)[0])


def load_partition(compression, window=LOAD_WINDOW):
    """How the top plate's load is carried over a strain window (model.md §8), as ratios of sums:
    plate force / (mean fluid pressure x top contact area), the fluid's share of what holds the
    touching wall particles up (fluid push / (fluid push + wall's own forces)), and the part of the
    plate force the pressure coupling's backstop gives (0 for LJ). NaN if the window is not reached."""
    compression = loading_branch(compression)
    e = compression["nominal_strain"]
    w = compression[(e >= window[0]) & (e <= window[1])]
    if w.empty or "load_fluid_N" not in w:
        return np.nan, np.nan, np.nan
    held = (w["load_fluid_N"] + w["load_wall_N"]).sum()
    force = w["plate_force_top_N"].sum()
    return (force / w["pressure_load_N"].sum(),
            w["load_fluid_N"].sum() / held if held else np.nan,
            w["load_backstop_N"].sum() / force if "load_backstop_N" in w and force else np.nan)


# The series of what flowed in or out of the energy account, in the solver's order.
ENERGY_FLOWS = tuple(term["column"] for term in ENERGY_TERMS if term["role"] != "stored")


def energy_account(drying, compression):
    """The energy account's verdicts (docs/model.md): the residual at the end of drying over all the
    energy that flowed in drying (the sum of the flows' magnitudes), and over the compression the residual's
    change and the losses as fractions of the plate work. None for a series without an account (one written
    before it, or a test's synthetic series); no compression verdicts without a compression."""
    out = {}
    if drying.empty or "energy_residual_J" not in drying:
        return out
    dried = drying.iloc[-1]
    flowed = sum(abs(dried.get(name, 0.0)) for name in ENERGY_FLOWS)
    out["drying_energy_residual_over_flow"] = dried["energy_residual_J"] / flowed if flowed else np.nan
    if len(compression):
        change = compression.iloc[-1] - dried[compression.columns]  # over the compression
        work = change["plate_work_J"]
        out.update({
            "compression_plate_work_nJ": work * 1e9,
            "compression_energy_residual_over_work": change["energy_residual_J"] / work if work else np.nan,
            "compression_viscous_loss_over_work": change["viscous_loss_J"] / work if work else np.nan,
            "compression_damping_loss_over_work": change["damping_loss_J"] / work if work else np.nan,
            "compression_plastic_loss_over_work": change.get("plastic_loss_J", np.nan) / work if work else np.nan,
        })
    return out


def load_unload(compression):
    """A loop's numbers (compression.unload_at_strain), NaN without one: the permanent set (the nominal
    strain when the cell left the top plate, the stage's end), the energy the loop dissipated (the plate's
    net work over it, the loop's area), and what of it the wall's plastic flow took."""
    back = unloading_branch(compression)
    if back.empty:
        return {"unload_permanent_set": np.nan, "loop_dissipated_nJ": np.nan, "loop_plastic_loss_nJ": np.nan}
    start, end = compression.iloc[0], compression.iloc[-1]
    return {"unload_permanent_set": end["nominal_strain"],
            "loop_dissipated_nJ": (end["plate_work_J"] - start["plate_work_J"]) * 1e9,
            "loop_plastic_loss_nJ": (end.get("plastic_loss_J", np.nan) - start.get("plastic_loss_J", np.nan)) * 1e9}


def summarise(ts):
    """Per-case metrics: end of drying, stresses at fixed strains, peak force, compression changes."""
    drying, compression = ts[ts["stage"] == 0], ts[ts["stage"] == 1]
    first, dried = ts.iloc[0], drying.iloc[-1]
    out = {
        "dried_M_over_M0": dried["fluid_mass_ratio"],
        "dried_V_over_V0": dried["volume_m3"] / first["volume_m3"],
        "dried_A_over_A0": dried["area_m2"] / first["area_m2"],
        "dried_mean_pressure_kPa": dried["mean_pressure_Pa"] / 1e3,
        "dried_wall_pressure_kPa": dried["wall_pressure_Pa"] / 1e3,
        "dried_wall_strain_mean": dried["wall_strain_mean"],
        "dried_plastic_strain_mean": dried.get("wall_plastic_strain_mean", np.nan),
        # A tissue's (NaN for one cell): the hull of all its walls, the air between its cells, bonds holding.
        "dried_tissue_V_over_V0": dried.get("tissue_volume_m3", np.nan) / first.get("tissue_volume_m3", np.nan),
        "dried_porosity": dried.get("porosity", np.nan),
        "dried_lamella_intact": dried.get("lamella_intact", np.nan),
        "lamella_bonds": first.get("lamella_intact", np.nan),
    }
    if len(compression):
        start, end = compression.iloc[0], compression.iloc[-1]
        out.update({
            "strain_reached": compression["nominal_strain"].max(),
            "peak_force_top_uN": compression["plate_force_top_N"].max() * 1e6,
            "compression_V_change": end["volume_m3"] / start["volume_m3"] - 1,
            "compression_A_change": end["area_m2"] / start["area_m2"] - 1,
            "end_mean_pressure_kPa": end["mean_pressure_Pa"] / 1e3,
            "end_wall_strain_mean": end["wall_strain_mean"],
            "end_lamella_intact": end.get("lamella_intact", np.nan),
            "end_plastic_strain_mean": end.get("wall_plastic_strain_mean", np.nan),
            **load_unload(compression),
        })
        for e in STRAINS:
            out[f"stress_kPa_at_{e:.2f}"] = value_at_strain(ts, e) / 1e3
            out[f"smoothed_stress_kPa_at_{e:.2f}"] = smoothed_stress_at_strain(ts, e) / 1e3
            out[f"mass_lost_at_{e:.2f}"] = (value_at_strain(ts, e, "compression_mass_lost")
                                            if "compression_mass_lost" in ts else np.nan)
            out[f"compression_time_us_at_{e:.2f}"] = (value_at_strain(ts, e, "compression_time_s") * 1e6
                                                     if "compression_time_s" in ts else np.nan)
            out[f"footprint_stress_kPa_at_{e:.2f}"] = (smoothed_stress_at_strain(ts, e, "footprint_stress_Pa") / 1e3
                                                       if "footprint_stress_Pa" in ts else np.nan)
        out["modulus_MPa_nominal"] = apparent_modulus(compression, "nominal_strain") / 1e6
        out["modulus_MPa_gauge"] = apparent_modulus(compression, "cell_strain") / 1e6
        out["gauge_strain_at_0.10"] = value_at_strain(ts, 0.10, "cell_strain") if "cell_strain" in ts else np.nan
        force_ratio, fluid_share, backstop_share = load_partition(compression)
        out["load_F_over_pA"] = force_ratio
        out["load_fluid_share"] = fluid_share
        out["load_backstop_share"] = backstop_share
    out.update(energy_account(drying, compression))
    return out


def tables(runs):
    """runs: [(Case, path of its result)] -> (timeseries table, summary table)."""
    series, summary = [], []
    for case, path in runs:
        ts = with_compression_series(timeseries(path))
        params = {"case": case.name, "dried": case.dried, "studies": " ".join(case.studies), **case.values,
                  **flatten(resolved_case(path))}
        # The case's parameters as columns, joined at once (one column at a time fragments the frame).
        series.append(pd.concat([ts, pd.DataFrame({k: [v] * len(ts) for k, v in params.items()}, index=ts.index)],
                                axis=1))
        summary.append({**params, **run_summary(path), **summarise(ts)})
    return pd.concat(series, ignore_index=True), pd.DataFrame(summary)
