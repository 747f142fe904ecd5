"""The tissue target's table and page (`snakemake --cores 2 tissue`, model.md §10): for each tissue and
dryness, the shrinkage and porosity at the end of drying, the stress at strains 0.05 and 0.10 against
the single cell's (stress = top-plate force / footprint at compression start, for both), and the
middle-lamella bonds: how many broke, when, and on which faces."""
import html
import pathlib

import numpy as np
import pandas as pd

from analysis import html_page, matrix
from analysis.bounds import REAL_LP  # a closed cell's compression L_p; any other drains it
from analysis.references import load as load_reference
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


def sides(row):
    """free (a cell or a cluster), or what a periodic slab's period did under the plates."""
    return row["compression.lateral"] if row.get("tissue.lateral") == "periodic" else "free"


def numerics(row):
    """The coupling and resolution a case ran with, in words (its single cell is the one alike)."""
    if row["coupling.model"] != "pressure":
        return "paper's (LJ)"
    return f"pressure coupling, h0/dx {row['fluid.h_over_dx']:.3g}"  # the resolved case's ratio (1.2, 1.25, 0.888)


def single_cell_of(rows, row):
    """The single cell of the same numerics, dryness, plate speed and compression L_p as `row` (None if
    none ran: a tissue at a speed no single cell ran at is compared with none)."""
    alike = rows[(rows["cells"] == 1) & np.isclose(rows["dryness"], row["dryness"])
                 & (rows["coupling.model"] == row["coupling.model"])
                 & np.isclose(rows["compression.plate_speed_m_s"], row["compression.plate_speed_m_s"])
                 & np.isclose(rows["compression.Lp_m_per_s_Pa"], row["compression.Lp_m_per_s_Pa"])]
    return alike.iloc[0] if len(alike) else None


def table(config, summary, series, runs, target="tissue"):
    """One row per case of the target's studies: numerics, cells, sides, drainage, dryness, shrinkage,
    porosity, stresses at nominal strains, the gauge, the apparent moduli (and their ratio to the
    single cell's of the same numerics, dryness, plate speed and drainage), bonds."""
    studies = [s for s in config["studies"] if matrix.target_of(config, s) == target]
    rows = summary[summary["studies"].str.split().apply(lambda s: bool(set(studies) & set(s)))].copy()
    out = []
    order = rows.assign(_sides=rows.apply(sides, axis=1)).sort_values(
        ["coupling.model", "cells", "_sides", "compression.plate_speed_m_s", "compression.Lp_m_per_s_Pa",
         "compression.end_strain", "dryness"], ascending=[True, True, True, True, True, True, False])
    for _, r in order.iterrows():
        alone = single_cell_of(rows, r)
        line = {"numerics": numerics(r), "cells": int(r["cells"]), "sides": sides(r),
                "plate [m/s]": r["compression.plate_speed_m_s"], "compression L_p": r["compression.Lp_m_per_s_Pa"],
                "X/X0": r["dryness"], "case": r["case"],
                "cells' V/V0 (dried)": r["dried_V_over_V0"], "tissue V/V0 (hull, dried)": r["dried_tissue_V_over_V0"],
                "porosity (dried)": r["dried_porosity"]}
        for e in STRAINS:
            stress = r.get(f"footprint_stress_kPa_at_{e}", np.nan)
            line[f"stress at {e} [kPa]"] = stress
            base = alone[f"footprint_stress_kPa_at_{e}"] if alone is not None else np.nan
            line[f"x single cell at {e}"] = stress / base if r["cells"] > 1 and base else np.nan
        line["gauge at nominal 0.10"] = r.get("gauge_strain_at_0.10", np.nan)
        line["modulus, nominal [MPa]"] = r.get("modulus_MPa_nominal", np.nan)
        line["modulus, gauge [MPa]"] = r.get("modulus_MPa_gauge", np.nan)
        base = alone["modulus_MPa_gauge"] if alone is not None else np.nan
        line["modulus x single cell"] = line["modulus, gauge [MPa]"] / base if r["cells"] > 1 and base else np.nan
        line["strain reached"] = r.get("strain_reached", np.nan)
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


def modulus_table(frame):
    """The apparent moduli [MPa] (over the nominal strain / over the interior cells' strain), a row per
    numerics, cells, sides and drainage, a column per dryness: one number per cell of the issue's table.
    Runs that stop short of the fit's window (nominal strain 0.05) are left out; '-' where the gauge
    stops short of it."""
    kind = ["numerics", "cells", "sides", "plate [m/s]", "compression L_p"]
    runs = frame[frame["modulus, nominal [MPa]"].notna()].drop_duplicates(kind + ["X/X0"])
    if runs.empty:
        return pd.DataFrame()
    def text(value):
        return f"{value:.2f}" if np.isfinite(value) else "-"
    cell = runs.assign(modulus=[f"{text(n)} / {text(g)}" for n, g in zip(runs["modulus, nominal [MPa]"],
                                                                         runs["modulus, gauge [MPa]"])])
    wide = cell.pivot_table(index=kind, columns="X/X0", values="modulus", aggfunc="first")
    wide = wide[sorted(wide.columns, reverse=True)]
    wide.columns = [f"X/X0 = {x:g}" for x in wide.columns]
    return wide.reset_index()


def apple_stress_kPa(config, names, root="."):
    """{reference label: its stress [kPa] at each of STRAINS}, interpolated on the reference curves."""
    out = {}
    for name in names:
        strain, stress = load_reference(config["references"][name], root)
        out[config["references"][name]["label"]] = [float(np.interp(float(e), strain, stress)) for e in STRAINS]
    return out


def conjecture_table(frame, apple_kPa):
    """Each periodic slab beside the single cell of the same numerics, dryness, plate speed and drainage:
    its stress over the cell's at STRAINS, its modulus over the interior strain over the cell's, and
    (fresh cells only) its stress over the apple references' at the same strains (their range)."""
    slabs = frame[frame["sides"].isin(["confined", "unconfined"]) & frame["x single cell at 0.05"].notna()]
    out = []
    for _, r in slabs.iterrows():
        fresh = np.isclose(r["X/X0"], 1.0)
        line = {"numerics": r["numerics"], "X/X0": r["X/X0"], "sides": r["sides"], "plate [m/s]": r["plate [m/s]"],
                "drainage": "closed" if np.isclose(r["compression L_p"], REAL_LP, rtol=1e-9, atol=0) else "drained"}
        for e in STRAINS:
            line[f"x single cell at {e}"] = r[f"x single cell at {e}"]
        line["modulus (gauge) x single cell"] = r["modulus x single cell"]
        for k, e in enumerate(STRAINS):
            ratios = [r[f"stress at {e} [kPa]"] / v[k] for v in apple_kPa.values()] if fresh else []
            finite = bool(ratios) and np.all(np.isfinite(ratios))
            line[f"x apple at {e}"] = f"{min(ratios):.1f}-{max(ratios):.1f}" if finite else "-"
        out.append(line)
    return pd.DataFrame(out)


def conjecture_answer(compared):
    """The paper's conjecture (a tissue's stress-strain gradient "significantly less" than one cell's),
    answered in one sentence from `conjecture_table`'s rows."""
    if compared.empty:
        return ("No periodic slab has run beside a single cell of the same numerics, dryness, plate speed "
                "and drainage yet, so the conjecture is not answered here.")
    def span(ratio):
        return f"{ratio.min():.2f}" if ratio.min() == ratio.max() else f"{ratio.min():.2f}-{ratio.max():.2f}"
    parts = []
    for e in STRAINS:
        ratio = compared[f"x single cell at {e}"].dropna()
        if len(ratio):
            parts.append(f"at nominal strain {e}, {int((ratio < 1).sum())} of {len(ratio)} carry less stress than "
                         f"their cell ({span(ratio)} times its stress)")
    modulus = compared["modulus (gauge) x single cell"].dropna()
    if len(modulus):
        parts.append(f"over the interior strain, {int((modulus < 1).sum())} of {len(modulus)} have a lower "
                     f"modulus ({span(modulus)} times the cell's)")
    slabs = f"{len(compared)} periodic slab{'s' if len(compared) > 1 else ''}"
    return (f"Is a tissue less stiff than one cell? Of {slabs} beside a single cell of the same numerics, "
            "dryness, plate speed and drainage, " + "; ".join(parts) + ".")


def write_page(path, config, frame, figure_files, target="tissue"):
    here = pathlib.Path(path).parent
    parts = ["<h1>Tissues: cells bonded by a middle lamella, dried and compressed</h1>",
             "<p>The paper's future work (docs/model.md §10). Each tissue is built of the paper's baseline cell, "
             "faceted where it meets its neighbours and bonded to them through middle-lamella bonds that soften past "
             "a peak strength and separate for good once they have taken their fracture energy; every cell dries "
             "by Eq 11 through its own wall. Two kinds of tissue: clusters (2 x 2 x 2, 3 x 3 x 3) between plates "
             "wider than them, with free sides, and a slab periodic in x and y (2 x 2 cells to a period, 4 layers; "
             "model.md §10b), whose period follows zero lateral stress as it dries and under the plates is held "
             "(confined) or keeps following (unconfined). Two numerics: the paper's (LJ coupling, level 1; "
             "its tissues' walls repel their fluid 3x harder than the single cell's), and the pressure coupling "
             "at h0/dx 1.2, level 1 (the slab, a cluster and the single cell beside it, at the paper's 1 m/s; "
             "the fresh slab at 4 m/s too), closed and drained (compression L_p 1e-6). Stress is the top-plate force over the footprint at the start of "
             "compression (the outline of all walls seen from above; a slab's period), for every tissue and the "
             "single cell alike; 'x single cell' is a tissue's stress or modulus over the single cell's of the same "
             "numerics, dryness, plate speed and drainage. The gauge is the interior cells' strain "
             "(model.md §10c). The tissue's volume is the convex hull of its walls, its porosity the part of that hull "
             "outside every cell. Choices and their reasons: model closures, 'Tissue'.</p>"]
    parts.append("<h2>Tissues against the single cell</h2>")
    parts.append(html_page.frame_table(frame.drop(columns=["case"])))
    moduli = modulus_table(frame)
    if len(moduli):
        parts.append("<h2>Apparent modulus at small strain</h2>")
        parts.append("<p>The slope of stress (force over the footprint at compression start; a periodic slab's "
                     "footprint is its period) against strain, fitted over strains 0.01-0.05, in MPa: over the "
                     "plates' nominal strain / over the interior cells' strain (a tissue's gauge between the "
                     "centroid planes of its layers away from the plates, model.md §10c; one cell's nominal "
                     "strain). Fresh apple tissue: initial tangent moduli 0.81-0.93 MPa (Chakespari et al., "
                     "figure tis08 fits the reconstructed curves alike). Closed: compression L_p 1e-12; "
                     "drained: 1e-6 (docs/model-closures.md, the drained bound).</p>")
        parts.append(html_page.frame_table(moduli))
    references = sorted({n for f in matrix.target_figures(config, target)
                         for n in config["figures"][f].get("references", [])})
    compared = conjecture_table(frame, apple_stress_kPa(config, references))
    parts.append("<h2>The paper's conjecture: is a tissue less stiff than one cell?</h2>")
    parts.append(f"<p>{html.escape(conjecture_answer(compared))} A ratio below 1 answers yes. 'x apple' is the "
                 "fresh slab's stress over the fresh apple tissue's at the same nominal strain (the range over "
                 f"{', '.join(html.escape(config['references'][n]['label']) for n in references) or 'no reference'}). "
                 "What the numbers point to: docs/model-closures.md, 'The tissue study'.</p>")
    if len(compared):
        parts.append(html_page.frame_table(compared))
    parts.append(html_page.figure_list(config, figure_files, here))
    html_page.write_page(path, f"cellsim {target}", parts)
