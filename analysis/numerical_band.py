"""The default study's numerical band: how far the paper's numerics (the LJ coupling, level 1) move when the
particle spacing is refined. It comes from the LJ ladder, study `convergence_resolution` (X/X0 1.0, 0.5 and
0.1 at 200 kPa, 1 m/s, levels 1-3), run by `snakemake --cores 2 numerical_band`. Its table is kept in
data/numerical_band/lj_ladder.csv, so that the default report's captions and claims carry the band without
running level 3 (config `numerical_band`)."""
import pathlib

import numpy as np
import pandas as pd

STUDY = "convergence_resolution"
DRYNESS = (1.0, 0.5, 0.1)
# The ladder's columns: the summary's (analysis/aggregate.py), stresses as the mean over +-0.01 strain.
QUANTITIES = {
    "smoothed_stress_kPa_at_0.05": "the stress at strain 0.05",
    "smoothed_stress_kPa_at_0.10": "the stress at 0.10",
    "smoothed_stress_kPa_at_0.15": "the stress at 0.15",
    "peak_force_top_uN": "the peak force",
    "compression_time_us_at_0.10": "the time to strain 0.10",
    "dried_V_over_V0": "the dried V/V0",
    "dried_A_over_A0": "the dried A/A0",
}
# What a figure plots -> the ladder's columns that bound it.
BY_QUANTITY = {
    "plate_stress_Pa": ["smoothed_stress_kPa_at_0.05", "smoothed_stress_kPa_at_0.10"],
    "plate_force_top_N": ["peak_force_top_uN"],
    "nominal_strain": ["compression_time_us_at_0.10"],
    "area_m2": ["dried_A_over_A0"],
    "volume_m3": ["dried_V_over_V0"],
}
SHAPE = ["dried_V_over_V0", "dried_A_over_A0"]  # a figure of shapes (or of the model) shows the dried cell


def ladder_table(summary):
    """The ladder's rows (one per dryness and level) from a summary table of its runs."""
    rows = summary[summary["studies"].str.split().apply(lambda s: STUDY in s)]
    table = pd.DataFrame({"dryness": rows["dryness"], "level": rows["resolution"], "n_wall": rows["cell.n_wall"],
                          "n_fluid": rows["cell.n_fluid"], "dt_ns": rows["time.dt_ns"],
                          **{column: rows[column] for column in QUANTITIES}})
    return table.sort_values(["dryness", "level"], ascending=[False, True]).reset_index(drop=True)


def read(path):
    table = pd.read_csv(path)
    missing = sorted(set(QUANTITIES) - set(table.columns))
    if missing:
        raise ValueError(f"{path}: the ladder table lacks {missing}")
    return table


def for_run(config, root="."):
    """The ladder's table where this run's base is the ladder's level 1 (the paper's numerics: the LJ coupling
    and the paper's particle counts and step), else None: a reduced or converged run has no such band."""
    spec = config.get("numerical_band")
    if not spec:
        return None
    table = read(pathlib.Path(root) / spec["file"])
    level_1 = table[table["level"] == 1].iloc[0]
    base = config["base"]
    paper = (base.get("coupling", {}).get("model") == "lennard_jones"
             and base["cell"].get("n_wall") == level_1["n_wall"] and base["cell"].get("n_fluid") == level_1["n_fluid"]
             and base.get("time", {}).get("dt_ns") == level_1["dt_ns"])
    return table if paper else None


def change(table, column, dryness, low=1, high=2):
    """Relative change of a ladder column from level `low` to level `high` at one dryness (NaN if absent)."""
    at = lambda level: table.loc[np.isclose(table["dryness"], dryness) & (table["level"] == level), column]  # noqa: E731
    a, b = at(low), at(high)
    return float(b.iloc[0] / a.iloc[0] - 1) if len(a) and len(b) else np.nan


def columns_of(spec):
    """The ladder columns that bound a figure: its plotted quantities', or the dried cell's for a picture."""
    if spec.get("family") != "curves":
        return SHAPE
    return [c for y in spec["y"] for c in BY_QUANTITY.get(y, [])] or SHAPE


def percent(value):
    if not np.isfinite(value):
        return "not reached"  # e.g. a compression that stopped short of the strain
    return f"{100 * value:+.2f} %" if abs(value) < 1e-3 else f"{100 * value:+.1f} %"


def sentence(table, columns, low=1, high=2):
    """'from level 1 to 2, the stress at strain 0.05 moves by +1.0 % / ... at X/X0 = 1.0 / 0.5 / 0.1; ...'"""
    parts = [f"{QUANTITIES[c]} by " + " / ".join(percent(change(table, c, x, low, high)) for x in DRYNESS)
             for c in columns]
    dryness = " / ".join(f"{x:g}" for x in DRYNESS)
    return f"from level {low} to {high}, {'; '.join(parts)} (X/X0 = {dryness})"


def caption(table, spec, source):
    """The band a default figure's caption states: level 1 to 2, and level 2 to 3 beside it."""
    columns = columns_of(spec)
    return (f"Numerical band (the LJ ladder, 200 kPa, 1 m/s, 150 um; {source}): {sentence(table, columns)}; "
            f"{sentence(table, columns, 2, 3)}.")


def claim_band(table, figure, config):
    """The level 1 to 2 change of what a claim's figure plots ('7', '11-12': the first figure named)."""
    spec = config["figures"].get(f"fig{int(figure.split('-')[0]):02d}", {"family": "curves", "y": ["plate_stress_Pa"]})
    return sentence(table, columns_of(spec))
