"""Reading cellsim result files (HDF5): time series, snapshots, the resolved case."""
import json

import h5py
import numpy as np
import pandas as pd


class IncompleteResult(RuntimeError):
    pass


def open_result(path):
    """A completed result file, open for reading; IncompleteResult naming the file if it is not one (a
    half-written or damaged file in a results folder, e.g. one copied in part)."""
    try:
        f = h5py.File(path, "r")
    except OSError as error:  # h5py's message does not name the file
        raise IncompleteResult(f"{path}: cannot be read as a cellsim result ({error}); delete it and run the "
                               f"workflow again, which runs its case anew") from error
    if f.attrs.get("completed", 0) != 1:
        f.close()
        raise IncompleteResult(f"{path}: not a completed cellsim result")
    return f


def timeseries(path):
    """All /timeseries datasets as a DataFrame (SI units, one row per record)."""
    with open_result(path) as f:
        return pd.DataFrame({name: np.asarray(d) for name, d in f["timeseries"].items()})


def resolved_case(path):
    with open_result(path) as f:
        return json.loads(f.attrs["case_json"])


def run_summary(path):
    """How the run went: the relaxation at rest, when steady state was reached (NaN if drying hit its
    cap), whether the compression stopped at its cap (compression.steps) before the end it was asked
    for, and the run's warning ('' if none)."""
    with open_result(path) as f:
        a = f.attrs
        return {"settle_iterations": int(a["settle_iterations"]), "settle_mass_ratio": float(a["settle_mass_ratio"]),
                "settle_volume_ratio": float(a["settle_volume_ratio"]),
                "drying_steady": bool(a["drying_steady"]), "drying_steady_time_us": float(a["drying_steady_time_s"]) * 1e6,
                "compression_at_cap": int(a.get("compression_reached_end", -1)) == 0,
                # V dP/dV at the end of drying (closed cells; NaN for SPH and for files from before it)
                "volumetric_modulus_MPa": float(a.get("volumetric_modulus_Pa", np.nan)) / 1e6,
                "warning": text(a["warning"])}


def text(attribute):
    """A string attribute as str: the solver writes fixed-length strings, which h5py reads as bytes."""
    return attribute.decode() if isinstance(attribute, bytes) else str(attribute)


def flatten(case):
    """{'cell': {'n_wall': 2067}} -> {'cell.n_wall': 2067}"""
    return {f"{section}.{key}": value for section, keys in case.items() if isinstance(keys, dict)
            for key, value in keys.items()}


def snapshots(path):
    """[(group name, time_s, stage)] in time order."""
    with open_result(path) as f:
        out = [(name, float(g.attrs["time_s"]), int(g.attrs["stage"])) for name, g in f["snapshots"].items()]
    return sorted(out, key=lambda s: s[1])


def snapshot(path, group):
    """Positions, plates and triangles of one snapshot (SI)."""
    with open_result(path) as f:
        g = f["snapshots"][group]
        return {
            "wall": g["wall_positions"][()], "fluid": g["fluid_positions"][()],
            "pressure": g["fluid_pressure"][()], "time_s": float(g.attrs["time_s"]),
            "stage": int(g.attrs["stage"]), "plate_top_z_m": float(g.attrs["plate_top_z_m"]),
            "plate_bottom_z_m": float(g.attrs["plate_bottom_z_m"]), "triangles": f["mesh/triangles"][()],
            "wall_cell": f["mesh/wall_cell"][()], "fluid_cell": f["mesh/fluid_cell"][()],
            "period_x_m": period_at(f, float(g.attrs["time_s"])),
        }


def period_at(f, time_s):
    """A periodic slab's period along x at the record nearest `time_s` (NaN for a cell or a cluster,
    and for files written before slabs)."""
    if "period_x_m" not in f["timeseries"]:
        return float("nan")
    times = f["timeseries/time_s"][()]
    return float(f["timeseries/period_x_m"][()][int(np.argmin(np.abs(times - time_s)))])


STRAIN_MOMENT_TOLERANCE = 0.01  # a 'strain_E' snapshot's nominal strain is E to within this


def _nearest_strain(path, snaps, strain):
    """The compression snapshot (group name) whose nominal strain, at the record nearest its time, is nearest
    `strain`."""
    compression = [s for s in snaps if s[2] == 1]
    if not compression:
        raise ValueError(f"{path}: no compression snapshot")
    with open_result(path) as f:
        times, strains = f["timeseries/time_s"][()], f["timeseries/nominal_strain"][()]
    at = [float(strains[int(np.argmin(np.abs(times - s[1])))]) for s in compression]
    best = int(np.argmin(np.abs(np.array(at) - strain)))
    if abs(at[best] - strain) > STRAIN_MOMENT_TOLERANCE:
        raise ValueError(f"{path}: no compression snapshot near strain {strain} (the nearest is at {at[best]:.3f})")
    return compression[best][0]


def pick_snapshot(path, moment, dried_path=None):
    """A snapshot by moment: 'end_of_drying' (last drying snapshot, from the dried file if the
    compression file has none), 'end', 'compression_K' (K-th of 4 evenly spaced in compression), or
    'strain_E' (the compression snapshot whose nominal strain is nearest E; an error where the run's
    snapshots stop more than 0.01 short of it or pass it by more)."""
    snaps = snapshots(path)
    if moment.startswith("strain_"):
        return snapshot(path, _nearest_strain(path, snaps, float(moment.split("_")[1])))
    if moment == "end":
        return snapshot(path, snaps[-1][0])
    if moment == "end_of_drying":
        drying = [s for s in snaps if s[2] == 0]
        if drying:
            return snapshot(path, drying[-1][0])
        if dried_path is None:
            raise ValueError(f"{path}: no drying snapshot and no dried file given")
        return snapshot(dried_path, snapshots(dried_path)[-1][0])
    if moment.startswith("compression_"):
        k = int(moment.split("_")[1])
        compression = [s for s in snaps if s[2] == 1]
        if not compression:
            raise ValueError(f"{path}: no compression snapshot")
        index = min(len(compression) - 1, round(k * (len(compression) - 1) / 4))
        return snapshot(path, compression[index][0])
    raise ValueError(f"unknown moment '{moment}'")
