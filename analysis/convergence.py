"""The convergence target's tables and page (`snakemake --cores 2 convergence`): for each convergence
study, the metrics of every case along its refined axis (resolution level, time step, or a swept
parameter: h0/dx, K, the plate speed), the relative change between successive cases and, where three
levels allow it, the observed order of convergence; the analytic anchors (analysis/anchors.py). The
criteria (docs/model-closures.md, "The verification ladder") are LIMITS, ENERGY_LIMIT and BACKSTOP_LIMIT
below, and the page states them from there (criteria_text). A swept parameter has no criterion: its table
says how much it moves the answer. The stress at a strain is the mean over the records within +-0.01
strain of it (aggregate.smoothed_stress_at_strain), so that the ripple of the plate contact from record to
record does not pass for a change of the curve."""
import html
import math
import pathlib

import numpy as np
import pandas as pd

from analysis.matrix import target_of
from analysis import html_page, matrix
from analysis.aggregate import rows_of

# (summary column, heading): what each case reports.
METRICS = [("smoothed_stress_kPa_at_0.05", "stress at strain 0.05 [kPa]"),
           ("smoothed_stress_kPa_at_0.10", "stress at strain 0.10 [kPa]"),
           ("peak_force_top_uN", "peak force [uN]"),
           ("dried_V_over_V0", "end-of-drying V/V0"),
           ("load_F_over_pA", "F / (p A_c), strain 0.05-0.15"),
           ("load_fluid_share", "fluid's share of the load"),
           ("load_backstop_share", "backstop's share of the load"),
           ("compression_energy_residual_over_work", "energy residual / plate work"),
           ("strain_reached", "strain reached")]
COMPARED = METRICS[:5]  # the relative changes and orders shown for these
# Per refined axis, the largest relative change between the two finest cases that counts as converged,
# per metric (an axis not named here is a sweep: no criterion).
LIMITS = {"resolution": {"smoothed_stress_kPa_at_0.05": 0.10, "smoothed_stress_kPa_at_0.10": 0.10,
                         "peak_force_top_uN": 0.10, "dried_V_over_V0": 0.10, "load_F_over_pA": 0.05},
          "dt_ns": {"smoothed_stress_kPa_at_0.05": 0.03, "smoothed_stress_kPa_at_0.10": 0.03}}
ENERGY_LIMIT, BACKSTOP_LIMIT = 0.01, 0.02  # of the plate work; of the plate force
AXIS_WORDS = {"resolution": "between the two finest resolution levels", "dt_ns": "between the two time steps"}


def percent(fraction):
    return f"{100 * fraction:.0f} %"


def criteria_text():
    """The criteria in words, from LIMITS, ENERGY_LIMIT and BACKSTOP_LIMIT (the one place they are set)."""
    parts = []
    for axis, limits in LIMITS.items():
        by_limit = {}
        for metric, limit in limits.items():
            by_limit.setdefault(limit, []).append(dict(METRICS)[metric].split(" [")[0])
        said = [f"{', '.join(names[:-1]) + ' and ' if len(names) > 1 else ''}{names[-1]} by less than {percent(limit)}"
                for limit, names in by_limit.items()]
        parts.append(f"{AXIS_WORDS.get(axis, axis)}, {'; '.join(said)}")
    return (f"Criteria: {'; '.join(parts)}; every compression keeps its energy account within "
            f"{percent(ENERGY_LIMIT)} of the plate work, and the pressure coupling's backstop carries under "
            f"{percent(BACKSTOP_LIMIT)} of the load.")
GROUPING_AXES = ("fluid", "coupling", "dryness")  # rows are grouped by these, in this order


def without_unread_coupling(rows):
    """The rows with a closed cell's coupling as "-": a cavity has no wall-fluid coupling to read."""
    if "fluid" in rows.columns and "coupling" in rows.columns:
        rows = rows.copy()
        rows.loc[rows["fluid"] == "cavity", "coupling"] = "-"
    return rows


def refined_axis(config, study):
    """The axis a convergence study refines: the one it gives more than one value besides the grouping
    axes (an axis with one value fixes a setting for the study); None for a comparison study."""
    vary = config["studies"][study]["vary"]
    varied = [a for a in vary if a not in GROUPING_AXES and len(vary[a]) > 1]
    if len(varied) > 1:
        raise ValueError(f"studies.{study}: a convergence study varies one axis besides {GROUPING_AXES}, got {varied}")
    return varied[0] if varied else None


def spacing(row):
    """The fluid particle spacing, up to a constant: (1 / N_f)^(1/3)."""
    return row["cell.n_fluid"] ** (-1.0 / 3.0)


def refinement(row, axis):
    """How fine a case is along the refined axis (larger: finer): 1/spacing, 1/dt, or for a sweep the
    case's value of the swept key (h0/dx, K, plate speed: the order of the table)."""
    if axis == "resolution":
        return 1.0 / spacing(row)
    if axis == "dt_ns":
        return 1.0 / row["time.dt_ns"]
    if axis == "smoothing":
        return row["fluid.h_over_dx"]
    return float(row[axis])


def relative_change(coarse, fine):
    return (fine - coarse) / abs(coarse) if coarse and np.isfinite(coarse) and np.isfinite(fine) else np.nan


def observed_order(f1, f2, f3, r12, r23):
    """Order p of f_h = f + C h^p from three levels (refinement ratios r12, r23, assumed equal: their
    mean is used); NaN where the changes do not shrink monotonically (no asymptotic range yet)."""
    d12, d23 = f2 - f1, f3 - f2
    if not all(np.isfinite([d12, d23])) or d12 == 0 or d23 == 0 or d12 * d23 < 0 or abs(d23) >= abs(d12):
        return np.nan
    return math.log(abs(d12) / abs(d23)) / math.log(0.5 * (r12 + r23))


def study_table(config, study, summary):
    """One row per case of the study, grouped, finest last, with the changes from the next coarser."""
    axis = refined_axis(config, study)
    rows = without_unread_coupling(rows_of(summary, study))
    rows["refinement"] = [refinement(r, axis) for _, r in rows.iterrows()]
    group_axes = [a for a in GROUPING_AXES if a in rows.columns]
    out = []
    for _, group in rows.groupby(group_axes if len(group_axes) > 1 else group_axes[0], sort=False):
        group = group.sort_values("refinement")
        previous = None
        for _, r in group.iterrows():
            line = {"study": study, "refined_axis": axis, **{a: r[a] for a in group_axes},
                    axis: r[axis], "case": r["case"], "n_fluid": int(r["cell.n_fluid"]), "n_wall": int(r["cell.n_wall"]),
                    "dt_ns": r["time.dt_ns"], **{m: r.get(m, np.nan) for m, _ in METRICS}}
            for m, _ in COMPARED:
                line[f"change_{m}"] = relative_change(previous[m], r[m]) if previous is not None else np.nan
            out.append(line)
            previous = r
        if len(group) == 3:
            r1, r2, r3 = (group.iloc[i] for i in range(3))
            ratios = (r2["refinement"] / r1["refinement"], r3["refinement"] / r2["refinement"])
            for m, _ in COMPARED:
                out[-1][f"order_{m}"] = observed_order(r1[m], r2[m], r3[m], *ratios)
    return pd.DataFrame(out)


def tables(config, summary, target="convergence"):
    """The convergence table of every refining study of the target, one frame."""
    studies = [s for s in config["studies"] if target_of(config, s) == target and refined_axis(config, s)]
    return pd.concat([study_table(config, s, summary) for s in studies], ignore_index=True)


def comparisons(config, summary, target="convergence"):
    """{study: its cases' metrics} for the target's studies that compare without refining."""
    out = {}
    for study in config["studies"]:
        if target_of(config, study) != target or refined_axis(config, study):
            continue
        rows = without_unread_coupling(rows_of(summary, study))
        axes = [a for a in GROUPING_AXES if a in config["studies"][study]["vary"]]
        out[study] = rows[axes + [m for m, _ in METRICS]].sort_values(axes, ascending=[True, False][:len(axes)])
    return out


def verdicts(config, table):
    """Per refining study and group: the largest change of each criterion's metric between the two finest
    refinements, against its limit ('incomplete' while a refinement of the study is missing, 'not reached'
    where the compression stopped short of a strain); a sweep gets none. For every study, the largest
    energy residual (against ENERGY_LIMIT of the plate work) and backstop share (BACKSTOP_LIMIT of the force)."""
    out = []
    for (study, axis), rows in table.groupby(["study", "refined_axis"], sort=False):
        levels = len(config["studies"][study]["vary"][axis])
        group_axes = [a for a in GROUPING_AXES if a in rows.columns and rows[a].notna().all()]
        for key, group in rows.groupby(group_axes if len(group_axes) > 1 else group_axes[0], sort=False):
            groups = dict(zip(group_axes, key if isinstance(key, tuple) else (key,)))
            line = {"study": study, **{a: groups.get(a, "") for a in GROUPING_AXES}}
            limits = LIMITS.get(axis)
            if limits:
                finest = group.iloc[-1]
                failing, missing = [], []
                for metric, limit in limits.items():
                    change = abs(finest.get(f"change_{metric}", np.nan))
                    if not np.isfinite(change):
                        missing.append(metric)
                    elif change >= limit:
                        failing.append(f"{dict(METRICS)[metric].split(' [')[0]} {100 * change:+.1f} % (limit {100 * limit:.0f} %)")
                line["between the two finest"] = "; ".join(failing) or "every change within its limit"
                line["converged"] = ("incomplete" if len(group) < levels else "no" if failing
                                     else "not reached" if missing else "yes")
            else:
                line["between the two finest"] = "a sweep: no criterion"
                line["converged"] = ""
            energy = group["compression_energy_residual_over_work"].abs().max()
            backstop = group["load_backstop_share"].abs().max() if "load_backstop_share" in group else np.nan
            line["largest |energy residual| / plate work [%]"] = 100 * energy
            line[f"energy within {percent(ENERGY_LIMIT)}"] = "yes" if energy < ENERGY_LIMIT else "no" if np.isfinite(energy) else ""
            line["largest backstop share [%]"] = 100 * backstop
            out.append(line)
    return pd.DataFrame(out)


# The studies whose runs measure an analytic anchor (analysis/anchors.py), and how; the ladder's fresh cells
# give Young-Laplace at 200 kPa as well.
ANCHOR_STUDIES = {"breathing_mode": "breathing", "young_laplace": "laplace", "membrane": "membrane"}
LADDER = "pressure_resolution"


def anchor_runs(config, cases):
    """[(kind, case name, resolution level)] of the anchor runs the config's convergence target has."""
    runs = []
    for name, case in cases.items():
        level = case.values.get("resolution", 1)
        for study in case.studies:
            if target_of(config, study) != "convergence":
                continue
            if study in ANCHOR_STUDIES:
                runs.append((ANCHOR_STUDIES[study], name, level))
            elif study == LADDER and case.values.get("dryness") == 1.0:
                runs.append(("laplace", name, level))
    return sorted(set(runs), key=lambda r: (list(ANCHOR_STUDIES.values()).index(r[0]), r[2], r[1]))


def readable(table):
    """The table with headings a reader understands and changes in %."""
    frame = table.drop(columns=["study", "refined_axis", "case"]).copy()
    if "fluid" in frame.columns:  # a closed cell has no fluid particles: its level is its wall's
        frame["n_fluid"] = frame["n_fluid"].astype(object).where(frame["fluid"] != "cavity", "-")
    for column in frame.columns:
        if column.startswith("change_"):
            frame[column] = 100 * frame[column]
    names = dict(METRICS)
    frame.columns = [names.get(c, c) if not c.startswith(("change_", "order_")) else
                     ("change of " if c.startswith("change_") else "order of ") +
                     names[c.split("_", 1)[1]].split(" [")[0] + (" [%]" if c.startswith("change_") else "")
                     for c in frame.columns]
    return frame.dropna(axis=1, how="all")


def bulk_modulus_note(table):
    """A sentence per dryness of the K sweep: the stress at strain 0.10 at each K and, from the two stiffest,
    the trend 1/K extrapolates to (K -> infinity, water's 2.2 GPa being 10-100 times the sweep's)."""
    rows = table[table["refined_axis"] == "K_MPa"]
    notes = []
    for dryness, group in rows.groupby("dryness", sort=False):
        group = group.sort_values("K_MPa")
        stress = group["smoothed_stress_kPa_at_0.10"].to_numpy()
        K = group["K_MPa"].to_numpy(dtype=float)
        if len(group) < 2 or not np.isfinite(stress[-2:]).all():
            continue
        # stress = s_inf + a / K through the two stiffest
        a = (stress[-2] - stress[-1]) / (1 / K[-2] - 1 / K[-1])
        limit = stress[-1] - a / K[-1]
        values = ", ".join(f"{s:.0f} kPa at K = {k:g} MPa" for s, k in zip(stress, K))
        paper = f" (the paper's 20 MPa: {100 * (stress[K == 20][0] / limit - 1):+.0f} %)" if (K == 20).any() else ""
        notes.append(f"X/X0 = {dryness:g}: stress at strain 0.10 {values}; through the two stiffest, "
                     f"stress = s + a/K gives s = {limit:.0f} kPa for an incompressible fluid{paper}.")
    return notes


def resolution_words(config):
    """The levels' particle counts and wall spacing over the lowest level's, from the resolution axis
    (its coupled cell sizes), e.g. "fluid count x1, x2.83, x8 and wall count x1, x2, x4: the wall's
    particle spacing x1, x0.707, x0.5 from level 1 to level 3"."""
    axis = config["axes"].get("resolution")
    if not axis:
        return "the particle count"
    base = {a: matrix.base_value(config, a) for a in config["axes"]}
    levels = sorted({int(axis["base_value"]), *(int(level) for level in axis.get("coupled", {}))})
    cells = [matrix.build(config, {**base, "resolution": level})[0]["cell"] for level in levels]
    fluid = ", ".join(f"x{c['n_fluid'] / cells[0]['n_fluid']:.3g}" for c in cells)
    wall = ", ".join(f"x{c['n_wall'] / cells[0]['n_wall']:.3g}" for c in cells)
    spacing = ", ".join(f"x{(cells[0]['n_wall'] / c['n_wall']) ** 0.5:.3g}" for c in cells)
    return (f"fluid count {fluid} and wall count {wall}: the wall's particle spacing {spacing} from level "
            f"{levels[0]} to level {levels[-1]}")


def write_page(path, config, table, figure_files, compared=None, target="convergence", summary=None, anchors=None):
    """summary: the target's cases, for the energy warning (html_page.energy_box); anchors: the analytic
    anchors' table (anchors.anchor_table)."""
    here = pathlib.Path(path).parent
    parts = ["<h1>Convergence: how much of a curve is the particle count</h1>",
             f"<p>Each convergence study refines one axis: the resolution ({resolution_words(config)}; r0 and the "
             "fill gap follow the mesh, and "
             "h0 follows it at a fixed h0/dx), the time step, or sweeps a parameter (h0/dx, the fluid's bulk modulus "
             "K, the plate speed). Changes are relative to the previous case; the order p is "
             "log(|f2 - f1| / |f3 - f2|) / log(r), with r the spacing ratio (sqrt 2), where the changes shrink. "
             "A closed cell (fluid: cavity, solved quasi-statically) has no fluid particles and no coupling: its "
             "level is its wall's, and it is the limit the SPH cells are measured against. "
             f"{criteria_text()} The load partition (F / (p A_c), the fluid's and the backstop's shares) is explained in "
             "docs/model.md §8.</p>"]
    if summary is not None:
        parts.append(html_page.energy_box(summary))
    parts.append("<h2>Verdicts</h2>" + html_page.frame_table(verdicts(config, table)))
    if anchors is not None and len(anchors):
        parts.append("<h2>Analytic anchors</h2><p>Results the model must meet that do not come from the model "
                     "(docs/model.md §9): the breathing mode of the closed cell against the lowest radial mode of a "
                     "compressible fluid sphere in an elastic shell (within 5 %); Young-Laplace, the pressure of a cell "
                     "at rest against 2T/R (within 2 %); the cell without contraction springs (k_wc = 0) pressed "
                     "between plates against the axisymmetric membrane solution for its own mesh (within 10 %).</p>"
                     + html_page.frame_table(anchors.drop(columns=["case"])))
    for study, rows in table.groupby("study", sort=False):
        parts.append(f"<h2>{html.escape(config['studies'][study].get('title', study))}</h2>")
        parts.append(html_page.frame_table(readable(rows)))
        if rows["refined_axis"].iloc[0] == "K_MPa":
            parts += [f"<p>{html.escape(note)}</p>" for note in bulk_modulus_note(rows)]
    for study, rows in (compared or {}).items():
        parts.append(f"<h2>{html.escape(config['studies'][study].get('title', study))}</h2>")
        parts.append(html_page.frame_table(rows.rename(columns=dict(METRICS))))
    parts.append(html_page.figure_list(config, figure_files, here))
    html_page.write_page(path, f"cellsim {target}", parts)
