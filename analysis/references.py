"""Reference data: a CSV of two columns and its config entry (units, provenance). Stress-strain curves
(`references`) and shrinkage lines (`shrinkage_references`: X/X0, V/V0)."""
import pathlib

import numpy as np

STRESS_TO_KPA = {"Pa": 1e-3, "kPa": 1.0, "MPa": 1e3}
STRAIN_TO_FRACTION = {"1": 1.0, "%": 0.01}


def columns(spec, root=".", names="strain, stress"):
    """The first two columns of a reference entry's CSV, as written."""
    path = pathlib.Path(root) / spec["file"]
    data = np.loadtxt(path, delimiter=",", comments="#", skiprows=spec.get("header_rows", 0), ndmin=2)
    if data.shape[1] < 2:
        raise ValueError(f"{path}: expected two columns ({names})")
    return data[:, 0], data[:, 1]


def load(spec, root="."):
    """(strain as a fraction, stress in kPa) of one reference entry."""
    strain, stress = columns(spec, root)
    return strain * STRAIN_TO_FRACTION[spec["strain_unit"]], stress * STRESS_TO_KPA[spec["stress_unit"]]


def load_shrinkage(spec, root="."):
    """(X/X0, V/V0) of one shrinkage reference entry."""
    return columns(spec, root, "X/X0, V/V0")
