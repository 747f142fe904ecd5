"""The cell in 3-D in the browser: for one case, a page (paper/cell_view.html) and its data, a script
that sets `CELL_DATA` (loaded with <script src>, so the page works from disk, offline). The data are
float32 arrays, base64-encoded: wall and fluid positions of up to MAX_DRYING + MAX_COMPRESSION
snapshots (drying from the dried state's file, compression from the case's), each fluid particle's
pressure and each wall particle's bond strain (the mean (l - l0)/l0 of its bonds); and each particle's
cell, so that a tissue's cells can be told apart."""
import base64
import json
import pathlib

import numpy as np

from analysis.results import open_result, snapshot, snapshots

MAX_DRYING, MAX_COMPRESSION = 5, 8  # snapshots per stage shown on the slider (evenly picked)
TEMPLATE = pathlib.Path(__file__).resolve().parent.parent / "paper" / "cell_view.html"


def evenly(items, n):
    if len(items) <= n:
        return list(items)
    return [items[round(i * (len(items) - 1) / (n - 1))] for i in range(n)]


def wall_bond_strain(wall, bonds, rest_length):
    """Per wall particle: the mean strain (l - l0)/l0 of the bonds that meet at it."""
    strain = np.linalg.norm(wall[bonds[:, 0]] - wall[bonds[:, 1]], axis=1) / rest_length - 1
    total, count = np.zeros(len(wall)), np.zeros(len(wall))
    for end in (0, 1):
        np.add.at(total, bonds[:, end], strain)
        np.add.at(count, bonds[:, end], 1)
    return total / np.maximum(count, 1)


def _b64(array, dtype="<f4"):
    return base64.b64encode(np.ascontiguousarray(array, dtype=dtype).tobytes()).decode("ascii")


def data(case_name, result, dried, plate_um=150.0):
    """CELL_DATA of one case: mesh, and for every picked snapshot its positions and colours."""
    picked = [(dried, s) for s in evenly([s for s in snapshots(dried) if s[2] == 0], MAX_DRYING)]
    picked += [(result, s) for s in evenly([s for s in snapshots(result) if s[2] == 1], MAX_COMPRESSION)]
    with open_result(result) as f:
        bonds, rest = f["mesh/bonds"][()], f["mesh/bond_rest_length"][()]
        wall_cell, fluid_cell = f["mesh/wall_cell"][()], f["mesh/fluid_cell"][()]
    frames = []
    for path, (group, time_s, stage) in picked:
        snap = snapshot(path, group)
        frames.append({"time_us": time_s * 1e6, "stage": "drying" if stage == 0 else "compression",
                       "wall": _b64(snap["wall"] * 1e6), "fluid": _b64(snap["fluid"] * 1e6),
                       "pressure_kPa": _b64(snap["pressure"] / 1e3),
                       "wall_strain": _b64(wall_bond_strain(snap["wall"], bonds, rest)),
                       "plates_um": [z * 1e6 if np.isfinite(z) else None
                                     for z in (snap["plate_top_z_m"], snap["plate_bottom_z_m"])]})
    return {"case": case_name, "n_wall": len(snap["wall"]), "n_fluid": len(snap["fluid"]), "plate_um": plate_um,
            "triangles": _b64(snap["triangles"], "<u4"), "n_cells": int(wall_cell.max()) + 1,
            "wall_cell": _b64(wall_cell, "<u4"), "fluid_cell": _b64(fluid_cell, "<u4"), "frames": frames}


def write(case_name, result, dried, html_path, data_path, plate_um=150.0):
    """Writes the page and its data script (named as the page expects: <case>.data.js beside it)."""
    payload = data(case_name, result, dried, plate_um)
    pathlib.Path(data_path).write_text("window.CELL_DATA = " + json.dumps(payload, allow_nan=False) + ";\n")
    page = TEMPLATE.read_text().replace("{{CASE}}", case_name).replace("{{DATA}}", pathlib.Path(data_path).name)
    pathlib.Path(html_path).write_text(page)
