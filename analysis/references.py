"""Experimental reference curves: a CSV (strain, stress) and its config entry (units, provenance)."""
import pathlib

import numpy as np

STRESS_TO_KPA = {"Pa": 1e-3, "kPa": 1.0, "MPa": 1e3}
STRAIN_TO_FRACTION = {"1": 1.0, "%": 0.01}


def load(spec, root="."):
    """(strain as a fraction, stress in kPa) of one reference entry."""
    path = pathlib.Path(root) / spec["file"]
    data = np.loadtxt(path, delimiter=",", comments="#", skiprows=spec.get("header_rows", 0), ndmin=2)
    if data.shape[1] < 2:
        raise ValueError(f"{path}: expected two columns (strain, stress)")
    return data[:, 0] * STRAIN_TO_FRACTION[spec["strain_unit"]], data[:, 1] * STRESS_TO_KPA[spec["stress_unit"]]
