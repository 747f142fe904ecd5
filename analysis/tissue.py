"""The tissue target's table and page (`snakemake --cores 2 tissue`, model.md §10): for each tissue and
dryness, the shrinkage and porosity at the end of drying, the stress at strains 0.05 and 0.10 against
the single cell's (stress = top-plate force / footprint at compression start, for both), and the
middle-lamella bonds: how many broke, when, and on which faces."""
import pathlib

import numpy as np
import pandas as pd

from analysis import report
from analysis.matrix import target_of
from analysis.results import open_result

STRAINS = ("0.05", "0.10")


def broken_bonds_by_face(path):
    """(bonds broken on faces between layers (normal along z, the plates' axis), on lateral faces) at
    the end of a run; (0, 0) for one cell."""
    with open_result(path) as f:
        if "lamella" not in f["mesh"]:
            return 0, 0
        bonds, cell = f["mesh/lamella"][()], f["mesh/wall_cell"][()]
        intact = f["state/lamella_intact"][()].astype(bool)
        first = f["snapshots"][sorted(f["snapshots"])[0]]["wall_positions"][()]
    centres = np.array([first[cell == c].mean(axis=0) for c in range(cell.max() + 1)])
    between = centres[cell[bonds[:, 1]]] - centres[cell[bonds[:, 0]]]
    layers = np.abs(between[:, 2]) > np.linalg.norm(between[:, :2], axis=1)
    return int((~intact & layers).sum()), int((~intact & ~layers).sum())


def first_break_strain(series):
    """The nominal strain at the first compression record with fewer intact bonds than at its start."""
    c = series[series["stage"] == 1]
    if c.empty:
        return np.nan
    fewer = c[c["lamella_intact"] < c["lamella_intact"].iloc[0]]
    return fewer["nominal_strain"].iloc[0] if len(fewer) else np.nan


def table(config, summary, series, runs, target="tissue"):
    """One row per case of the target's studies: cells, dryness, shrinkage, porosity, stresses (and
    their ratio to the single cell's at the same dryness), bonds."""
    studies = [s for s in config["studies"] if target_of(config, s) == target]
    rows = summary[summary["studies"].str.split().apply(lambda s: bool(set(studies) & set(s)))].copy()
    single = rows[rows["cells"] == 1].set_index("dryness")
    out = []
    for _, r in rows.sort_values(["cells", "dryness"], ascending=[True, False]).iterrows():
        line = {"cells": int(r["cells"]), "X/X0": r["dryness"], "case": r["case"],
                "cells' V/V0 (dried)": r["dried_V_over_V0"], "tissue V/V0 (hull, dried)": r["dried_tissue_V_over_V0"],
                "porosity (dried)": r["dried_porosity"]}
        for e in STRAINS:
            stress = r.get(f"footprint_stress_kPa_at_{e}", np.nan)
            line[f"stress at {e} [kPa]"] = stress
            alone = single["footprint_stress_kPa_at_" + e].get(r["dryness"], np.nan) if len(single) else np.nan
            line[f"x single cell at {e}"] = stress / alone if r["cells"] > 1 and alone else np.nan
        if r["cells"] > 1:
            bonds = r["lamella_bonds"]
            line.update({"bonds": int(bonds), "broken in drying": int(bonds - r["dried_lamella_intact"]),
                         "broken in compression": int(r["dried_lamella_intact"] - r.get("end_lamella_intact", np.nan))
                         if np.isfinite(r.get("end_lamella_intact", np.nan)) else np.nan,
                         "first break at strain": first_break_strain(series[series["case"] == r["case"]])})
            layers, lateral = broken_bonds_by_face(runs[r["case"]])
            line.update({"broken between layers": layers, "broken on lateral faces": lateral})
        out.append(line)
    return pd.DataFrame(out)


def write_page(path, config, frame, figure_files, target="tissue"):
    here = pathlib.Path(path).parent
    parts = ["<h1>Tissues: cells bonded by a middle lamella, dried and compressed</h1>",
             "<p>The paper's future work (docs/model.md §10). Each tissue is built of the paper's baseline cell, "
             "faceted where it meets its neighbours and bonded to them through middle-lamella bonds that soften past "
             "a peak strength and separate for good once they have taken their fracture energy; every cell dries "
             "by Eq 11 through its own wall, and the tissue is compressed between plates wider than it. A tissue's "
             "walls repel its fluid 3x harder than the single cell's (coupling.repulsion_f0_N_m): its bonded cells "
             "reach several times the single cell's pressure. Stress is the top-plate force over the footprint "
             "(the outline of all walls seen from above) at the start of compression, for the tissues and the single cell alike; 'x single "
             "cell' is the tissue's stress over the single cell's at the same dryness and strain. The tissue's "
             "volume is the convex hull of its walls, its porosity the part of that hull outside every cell. "
             "Choices and their reasons: model closures, 'Tissue'.</p>"]
    parts.append("<h2>Tissues against the single cell</h2>")
    parts.append(report.frame_table(frame.drop(columns=["case"])))
    parts.append(report.figure_list(config, figure_files, here))
    report.write_page(path, f"cellsim {target}", parts)
