"""A design study's runs as one table (issue 70): a row per case with its role (train, held_out, check), its
factors' values and what the emulators learn: the dried V/V0, the volumetric modulus eps, and the stress at
strains 0.02 to 0.20 (kPa, smoothed over +-0.01 of strain: a dynamic cell's contact ripple is not the
emulator's to learn), at 0.05 too."""
import numpy as np
import pandas as pd

from analysis import aggregate, matrix
from analysis.results import run_summary, timeseries

STRAINS = tuple(round(0.02 * k, 2) for k in range(1, 11))  # the slider page's curve: 0.02, 0.04, ..., 0.20
RECORDED_STRAINS = tuple(sorted(set(STRAINS) | {0.05}))       # and 0.05, where the ladder judges convergence
DRYING_OUTPUTS = ("dried_V_over_V0", "volumetric_modulus_MPa")


def stress_column(strain):
    return f"stress_kPa_at_{strain:.2f}"


STRESS_OUTPUTS = tuple(stress_column(e) for e in STRAINS)
RECORDED_STRESS = tuple(stress_column(e) for e in RECORDED_STRAINS)


def outputs(path, compressed):
    """What a run gives the emulators: the drying's two outputs, and the stress curve if it was compressed."""
    ts = aggregate.with_compression_series(timeseries(path))
    drying = ts[ts["stage"] == 0]
    out = {"dried_V_over_V0": drying["volume_m3"].iloc[-1] / ts["volume_m3"].iloc[0],
           "volumetric_modulus_MPa": run_summary(path)["volumetric_modulus_MPa"]}
    if compressed:
        out.update({stress_column(e): aggregate.smoothed_stress_at_strain(ts, e) / 1e3 for e in RECORDED_STRAINS})
        out["strain_reached"] = ts.loc[ts["stage"] == 1, "nominal_strain"].max()
    return out


def table(config, study, cases, files, compressed):
    """One row per case of the design study: case, role, the axes' values (the factors among them) and the
    outputs. files: {case name: result file} (the compressed run, or the dried state if not compressed)."""
    roles = matrix.design_roles(config, study)
    rows = []
    for name, path in files.items():
        rows.append({"case": name, "role": roles[name], **cases[name].values, **outputs(path, compressed)})
    frame = pd.DataFrame(rows)
    missing = [c for c in STRESS_OUTPUTS if compressed and frame[c].isna().any()]
    if missing:
        short = frame.loc[frame[missing[-1]].isna(), "case"].tolist()
        raise ValueError(f"study {study}: {len(short)} runs do not reach strain {STRAINS[-1]} + 0.01 (e.g. {short[0]}); "
                         f"raise the design's set: compression.steps or its end_strain")
    return frame


def wide_by(frame, factors, axes):
    """A design run at several values of some fixed axes (the calibration's moisture levels) as one row per
    design point: each output column once per combination, named 'output@axis=value' (axes sorted)."""
    keep = [c for c in frame.columns if c in DRYING_OUTPUTS or c in RECORDED_STRESS]
    if not axes:
        return frame[list(factors) + ["role"] + keep].reset_index(drop=True)
    parts = []
    keys = sorted(axes)
    for values, rows in frame.groupby(keys if len(keys) > 1 else keys[0]):
        values = values if len(keys) > 1 else (values,)
        suffix = "".join(f"@{a}={v:g}" for a, v in zip(sorted(axes), values))
        part = rows.set_index(list(factors) + ["role"])[keep]
        parts.append(part.rename(columns={c: c + suffix for c in keep}))
    return pd.concat(parts, axis=1).reset_index()


def finite(frame, columns):
    """The rows whose columns are all finite (a run whose ε could not be measured is left out)."""
    return frame[np.isfinite(frame[list(columns)].to_numpy(dtype=float)).all(axis=1)]
