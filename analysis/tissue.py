"""The tissue target's table and page (`snakemake --cores 2 tissue`, model.md §10): for each tissue and
dryness, the shrinkage and porosity at the end of drying, the stress at strains 0.05 and 0.10 against
the single cell's (stress = top-plate force / footprint at compression start, for both), and the
middle-lamella bonds: how many broke, when, and on which faces."""
import html
import pathlib

import numpy as np
import pandas as pd

from analysis import html_page, matrix
from analysis.aggregate import MODULUS_WINDOW  # the strains the moduli are fitted over
from analysis.bounds import REAL_LP  # a sealed cell's compression L_p; any other drains it
from analysis.figures.modulus import reference_modulus_MPa  # the fit the figures draw
from analysis.references import load as load_reference
from analysis.results import open_result

STRAINS = ("0.05", "0.10")


def lp_words(lp):
    """A permeability as a reader writes it: 1e-12, 1e-6 [m/(s Pa)]."""
    mantissa, exponent = f"{lp:e}".split("e")
    return f"{mantissa.rstrip('0').rstrip('.')}e{int(exponent)}"


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


# The paper's wall particles a cell at resolution levels 1-3 (config axes.resolution), and its bending k_b.
LEVEL_OF_N_WALL = {2067: 1, 4134: 2, 8268: 3}
PAPER_BENDING_J = 1e-10
PAPER_K_MPA = 20


def numerics(row):
    """The fluid, scheme, coupling and resolution a case ran with, in words, with what differs from the
    paper's wall and K (its single cell is the one alike: `single_cell_of`)."""
    if row["fluid.model"] == "cavity":
        words = ["closed cells, " + ("quasi-static" if row["time.scheme"] == "quasi_static" else "dynamic")]
    elif row["coupling.model"] != "pressure":
        words = ["paper's (LJ)"]
    else:  # the resolved case's ratio (1.2, 1.25, 0.888)
        words = [f"SPH, pressure coupling, h0/dx {row['fluid.h_over_dx']:.3g}"]
    level = LEVEL_OF_N_WALL.get(int(row["cell.n_wall"]))
    words.append(f"level {level}" if level else f"{int(row['cell.n_wall'])} wall particles a cell")
    if not np.isclose(row["wall.bending_stiffness_J"], PAPER_BENDING_J, rtol=1e-9, atol=0):
        words.append(f"k_b {row['wall.bending_stiffness_J']:.2g} J")
    if not np.isclose(row["fluid.bulk_modulus_MPa"], PAPER_K_MPA, rtol=1e-9, atol=0):
        words.append(f"K {row['fluid.bulk_modulus_MPa']:g} MPa")
    return ", ".join(words)


# What a single cell shares with the tissue it is compared with, besides the numerics' words.
ALIKE_KEYS = ["dryness", "compression.plate_speed_m_s", "compression.Lp_m_per_s_Pa"]


def single_cell_of(rows, row):
    """The single cell of the same numerics, dryness, plate speed and compression L_p as `row` (None if
    none ran: a tissue at a speed no single cell ran at is compared with none)."""
    cells = rows[rows["cells"] == 1]
    alike = cells[(cells.apply(numerics, axis=1) == numerics(row))
                  & np.logical_and.reduce([np.isclose(cells[k], row[k]) for k in ALIKE_KEYS])]
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
        line.update(energy_columns(r, runs[r["case"]]))
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


def energy_columns(row, path):
    """The energy account of a case (docs/model.md §8): its residual at the end of drying over the energy
    that flowed, over the compression as a share of the plate work, and a periodic slab's period loss
    (the viscous follower's, in drying and under the plates)."""
    with open_result(path) as f:
        series = f["timeseries"]
        loss = series["period_loss_J"][()] if "period_loss_J" in series else np.full(1, np.nan)
        stage = series["stage"][()]
    dried = np.nonzero(stage == 0)[0]
    loss_dried = loss[dried[-1]] if len(dried) and len(loss) == len(stage) else np.nan
    return {"energy residual, drying / flows": row.get("drying_energy_residual_over_flow", np.nan),
            "energy residual, compression / plate work": row.get("compression_energy_residual_over_work", np.nan),
            "period loss, drying [nJ]": loss_dried * 1e9,
            "period loss, compression [nJ]": (loss[-1] - loss_dried) * 1e9}


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
                "drainage": "sealed" if np.isclose(r["compression L_p"], REAL_LP, rtol=1e-9, atol=0) else "drained"}
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


def reference_moduli(config, names, root="."):
    """{label: (the reconstructed curve's modulus fitted as the runs' are [MPa], the source's initial tangent
    modulus [MPa] or NaN)} of the apple references."""

    return {config["references"][n]["label"]: (reference_modulus_MPa(config, n, root),
                                               config["references"][n].get("initial_modulus_MPa", np.nan))
            for n in names}


def check_table(frame):
    """Each case of another fluid beside the SPH slab of the same cells, sides, drainage and dryness: its
    stresses and moduli over the SPH slab's (the check of the closed cells, target tissue_check)."""
    sph = frame[frame["numerics"].str.startswith("SPH")]
    keys = ["cells", "sides", "compression L_p", "X/X0"]
    out = []
    for _, r in frame[~frame.index.isin(sph.index)].iterrows():
        twin = sph[np.logical_and.reduce([np.isclose(sph[k], r[k]) if k != "sides" else sph[k] == r[k] for k in keys])]
        if twin.empty:
            continue
        s = twin.iloc[0]
        line = {"numerics": r["numerics"], "against": s["numerics"], **{k: r[k] for k in keys}}
        for column in [f"stress at {e} [kPa]" for e in STRAINS] + ["modulus, nominal [MPa]", "modulus, gauge [MPa]"]:
            line[column] = r[column]
            line[f"{column.split(' [')[0]} / SPH's - 1"] = r[column] / s[column] - 1
        line["gauge at nominal 0.10"] = r["gauge at nominal 0.10"]
        out.append(line)
    return pd.DataFrame(out)


def texture_analyser_case(frame):
    """The case nearest a texture analyser's test (drained, and as slow as was run): the fresh slab drained,
    quasi-static if one ran, else at its slowest plate; None without a drained fresh slab."""
    slabs = frame[frame["sides"].isin(["confined", "unconfined"]) & np.isclose(frame["X/X0"], 1.0)
                  & ~np.isclose(frame["compression L_p"], REAL_LP, rtol=1e-9, atol=0)
                  & frame["modulus, gauge [MPa]"].notna()]
    if slabs.empty:
        return None
    slow = slabs.assign(_qs=slabs["numerics"].str.contains("quasi-static"))
    return slow.sort_values(["_qs", "plate [m/s]", "sides"], ascending=[False, True, True]).iloc[0]


def conjecture_paragraph(compared, frame, apple):
    """The paper's conjecture answered in one paragraph, every number from this run's tables: the slab over
    its cell, its modulus beside the cell's and the apple tissue's, and what a texture analyser would read."""
    text = [conjecture_answer(compared)]
    fresh = frame[np.isclose(frame["X/X0"], 1.0) & np.isclose(frame["compression L_p"], REAL_LP, rtol=1e-9, atol=0)]
    slab = fresh[(fresh["cells"] > 1) & (fresh["sides"] == "confined")]
    cell = fresh[(fresh["cells"] == 1) & fresh["numerics"].isin(slab["numerics"].iloc[:1])]
    measured = [m for _, m in apple.values() if np.isfinite(m)]
    apple_words = (f"the apple tissue's initial tangent modulus of {min(measured):.2f}-{max(measured):.2f} MPa"
                   if measured else "no measured modulus")
    if len(slab) and len(cell):
        s, c = slab.iloc[0], cell.iloc[0]
        text.append(f"Fresh, sealed and confined ({s['numerics']}), the slab's modulus over its interior strain is "
                    f"{s['modulus, gauge [MPa]']:.2f} MPa and over the plates' strain {s['modulus, nominal [MPa]']:.2f} "
                    f"MPa, the single cell's {c['modulus, gauge [MPa]']:.2f} MPa, beside {apple_words}.")
    near = texture_analyser_case(frame)
    if near is not None:
        def times_apple(modulus):
            ratio = [modulus / m for m in measured]
            return f" ({min(ratio):.1f}-{max(ratio):.1f} times the apple tissue's)" if ratio else ""
        text.append(f"A texture analyser presses drained tissue slowly; the closest case run here is the fresh slab "
                    f"drained (compression L_p {near['compression L_p']:g}), {near['sides']}, {near['numerics']} at "
                    f"{near['plate [m/s]']:g} m/s: its modulus is {near['modulus, nominal [MPa]']:.2f} MPa over the "
                    f"plates' strain{times_apple(near['modulus, nominal [MPa]'])} and "
                    f"{near['modulus, gauge [MPa]']:.2f} MPa over the interior strain"
                    f"{times_apple(near['modulus, gauge [MPa]'])}, whose gauge reads {near['gauge at nominal 0.10']:.3f} "
                    "at nominal strain 0.10 (a drained slab yields at a plateau: the interior fit then spans it).")
    return " ".join(text)


def study_list(config, target):
    """The target's studies, each with its title and its number of cases, as an HTML list (from config)."""
    items = []
    for name, spec in config["studies"].items():
        if matrix.target_of(config, name) != target:
            continue
        count = int(np.prod([len(v) for v in spec.get("vary", {}).values()]))
        items.append(f"<li><code>{html.escape(name)}</code>: {html.escape(spec.get('title', name))} "
                     f"({count} case{'s' if count != 1 else ''})</li>")
    return "<ul>" + "".join(items) + "</ul>"


def write_page(path, config, frame, figure_files, target="tissue", summary=None):
    """The target's page: its studies, warnings, the tissue table, the slab against its cell, the moduli
    beside the apple tissue's, the check against the SPH slab where it ran, the conjecture, the figures."""
    here = pathlib.Path(path).parent
    parts = [f"<h1>Tissues: cells bonded by a middle lamella, dried and compressed (target <code>{html.escape(target)}</code>)</h1>",
             "<p>The paper's future work (docs/model.md §10). Each tissue is built of the paper's baseline cell, "
             "faceted where it meets its neighbours and bonded to them through middle-lamella bonds that soften past "
             "a peak strength and separate for good once they have taken their fracture energy; every cell dries "
             "by Eq 11 through its own wall. A slab is periodic in x and y (model.md §10b): its period follows "
             "zero lateral stress as it dries and under the plates is held (confined) or keeps following "
             "(unconfined). A closed cell (fluid.model = cavity) holds one uniform pressure, in the dynamic scheme "
             "(the leapfrog, with the plate's rate) or the quasi-static one. This target's studies:</p>",
             study_list(config, target),
             "<p>Stress is the top-plate force over the footprint at the start of compression (the outline of all "
             "walls seen from above; a slab's period), for every tissue and the single cell alike; 'x single cell' "
             "is a tissue's stress or modulus over the single cell's of the same numerics, dryness, plate speed and "
             "drainage. The gauge is the interior cells' strain (model.md §10c). The tissue's volume is the convex "
             "hull of its walls, its porosity the part of that hull outside every cell. The energy columns: the "
             "account's residual over the energy that flowed in drying and over the plate work in compression, and "
             "the period's loss (its own term of the account). Choices and their reasons: model closures, "
             "'Tissue'.</p>"]
    if summary is not None:
        parts.append(html_page.warnings_box(summary))
    parts.append("<h2>Tissues against the single cell</h2>")
    parts.append(html_page.frame_table(frame.drop(columns=["case"])))
    references = sorted({n for f in matrix.target_figures(config, target)
                         for n in config["figures"][f].get("references", [])})
    compared = conjecture_table(frame, apple_stress_kPa(config, references))
    if len(compared):
        parts.append("<h2>The slab against its cell</h2>")
        parts.append("<p>Each periodic slab beside the single cell of the same numerics, dryness, plate speed and "
                     "drainage: its stress and its modulus over the interior strain over the cell's; 'x apple' is "
                     "the fresh slab's stress over the fresh apple tissue's at the same nominal strain.</p>")
        parts.append(html_page.frame_table(compared))
    moduli = modulus_table(frame)
    apple = reference_moduli(config, references)
    if len(moduli):
        parts.append("<h2>Apparent modulus at small strain</h2>")
        low, high = MODULUS_WINDOW
        drained = ", ".join(lp_words(lp) for lp in sorted(set(frame["compression L_p"]))
                            if not np.isclose(lp, REAL_LP, rtol=1e-9, atol=0)) or "none"
        parts.append("<p>The slope of stress (force over the footprint at compression start; a periodic slab's "
                     f"footprint is its period) against strain, fitted over strains {low:g}-{high:g}, in MPa: over "
                     "the plates' nominal strain / over the interior cells' strain (a tissue's gauge between the "
                     "centroid planes of its layers away from the plates, model.md §10c; one cell's nominal "
                     f"strain). Sealed: compression L_p {lp_words(REAL_LP)}; drained: {drained} "
                     "(docs/model-closures.md, the drained bound).</p>")
        parts.append(html_page.frame_table(moduli))
        if apple:
            rows = pd.DataFrame([{"fresh apple tissue": label, "reconstructed curve fitted alike [MPa]": fitted,
                                  "initial tangent modulus, as published [MPa]": published}
                                 for label, (fitted, published) in apple.items()])
            parts.append(html_page.frame_table(rows))
    checked = check_table(frame)
    if len(checked):
        parts.append("<h2>The closed cells against the SPH slab</h2>")
        parts.append("<p>The same slab with the SPH fluid (pressure coupling): each other fluid's stresses and "
                     "moduli, and their change from the SPH slab's.</p>")
        parts.append(html_page.frame_table(checked))
    parts.append("<h2>The paper's conjecture: is a tissue less stiff than one cell?</h2>")
    parts.append(f"<p>{html.escape(conjecture_paragraph(compared, frame, apple))} A ratio below 1 answers yes. "
                 "What the numbers point to: docs/findings.md and docs/model-closures.md, 'The tissue study'.</p>")
    parts.append(html_page.figure_list(config, figure_files, here))
    html_page.write_page(path, f"cellsim {target}", parts)
