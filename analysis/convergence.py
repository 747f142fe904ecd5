"""The convergence target's tables and page (`snakemake --cores 2 convergence`): for each convergence
study, the metrics of every case along its refined axis (resolution level or time step), the relative
change between successive refinements and, where three levels allow it, the observed order of
convergence. Criteria (docs/model-closures.md): resolution, stress changes by less than 10 % between
the two finest levels; time step, by less than 3 % between 1 and 0.5 ns. The stress at a strain is the
mean over the records within +-0.01 strain of it (aggregate.smoothed_stress_at_strain), so that the
ripple of the plate contact from record to record does not pass for a change of the curve."""
import html
import math
import pathlib

import numpy as np
import pandas as pd

from analysis.matrix import target_of
from analysis import report

# (summary column, heading): what each case reports.
METRICS = [("smoothed_stress_kPa_at_0.05", "stress at strain 0.05 [kPa]"),
           ("smoothed_stress_kPa_at_0.10", "stress at strain 0.10 [kPa]"),
           ("peak_force_top_uN", "peak force [uN]"),
           ("dried_V_over_V0", "end-of-drying V/V0"),
           ("load_F_over_pA", "F / (p A_c), strain 0.05-0.15"),
           ("load_fluid_share", "fluid's share of the load")]
COMPARED = METRICS[:4]  # the relative changes and orders shown for these
LIMITS = {"resolution": 0.10, "dt_ns": 0.03}  # the largest relative change that counts as converged
GROUPING_AXES = ("coupling", "dryness")  # rows are grouped by these, in this order


def refined_axis(config, study):
    """The axis a convergence study refines: the one it varies besides the grouping axes (None for a
    comparison study, which varies only those)."""
    varied = [a for a in config["studies"][study]["vary"] if a not in GROUPING_AXES]
    if len(varied) > 1:
        raise ValueError(f"studies.{study}: a convergence study varies one axis besides {GROUPING_AXES}, got {varied}")
    return varied[0] if varied else None


def spacing(row):
    """The fluid particle spacing, up to a constant: (1 / N_f)^(1/3)."""
    return row["cell.n_fluid"] ** (-1.0 / 3.0)


def refinement(row, axis):
    """How fine a case is along the refined axis (larger: finer): 1/spacing, or 1/dt."""
    return 1.0 / spacing(row) if axis == "resolution" else 1.0 / row["time.dt_ns"]


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
    rows = summary[summary["studies"].str.split().apply(lambda s: study in s)].copy()
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
        rows = summary[summary["studies"].str.split().apply(lambda s: study in s)]
        axes = [a for a in GROUPING_AXES if a in config["studies"][study]["vary"]]
        out[study] = rows[axes + [m for m, _ in METRICS]].sort_values(axes, ascending=[True, False][:len(axes)])
    return out


def verdicts(config, table):
    """Per study and group: the largest change of the stresses between the two finest refinements,
    against the study's limit ('incomplete' while a refinement of the study is missing)."""
    out = []
    for (study, axis), rows in table.groupby(["study", "refined_axis"], sort=False):
        levels = len(config["studies"][study]["vary"][axis])
        group_axes = [a for a in GROUPING_AXES if a in rows.columns and rows[a].notna().all()]
        for key, group in rows.groupby(group_axes if len(group_axes) > 1 else group_axes[0], sort=False):
            finest = group.iloc[-1]
            changes = [abs(finest[f"change_{m}"]) for m, _ in METRICS[:2]]
            worst = max(changes) if all(np.isfinite(changes)) else np.nan
            limit = LIMITS.get(axis, 0.10)
            verdict = ("incomplete" if len(group) < levels else "not reached" if not np.isfinite(worst)
                       else "yes" if worst < limit else "no")
            groups = dict(zip(group_axes, key if isinstance(key, tuple) else (key,)))
            out.append({"study": study, **{a: groups.get(a, "") for a in GROUPING_AXES},
                        "largest stress change between the two finest [%]": 100 * worst, "limit [%]": 100 * limit,
                        "converged": verdict})
    return pd.DataFrame(out)


def readable(table):
    """The table with headings a reader understands and changes in %."""
    frame = table.drop(columns=["study", "refined_axis", "case"]).copy()
    for column in frame.columns:
        if column.startswith("change_"):
            frame[column] = 100 * frame[column]
    names = dict(METRICS)
    frame.columns = [names.get(c, c) if not c.startswith(("change_", "order_")) else
                     ("change of " if c.startswith("change_") else "order of ") +
                     names[c.split("_", 1)[1]].split(" [")[0] + (" [%]" if c.startswith("change_") else "")
                     for c in frame.columns]
    return frame.dropna(axis=1, how="all")


def write_page(path, config, table, figure_files, compared=None, target="convergence", summary=None):
    """summary: the target's cases, for the energy warning (report.energy_box)."""
    here = pathlib.Path(path).parent
    parts = ["<h1>Convergence: how much of a curve is the particle count</h1>",
             "<p>Each convergence study refines one axis: the resolution (fluid count x1, x2.83, x8 and wall count "
             "x1, x2, x4: the particle spacing halves from level 1 to level 3; h0, r0 and the fill gap follow the mesh) "
             "or the time step (1 and 0.5 ns). Changes are relative to the next coarser case; the order p is "
             "log(|f2 - f1| / |f3 - f2|) / log(r), with r the spacing ratio (sqrt 2), where the changes shrink. "
             "Criteria: a stress change below 10 % between the two finest levels, below 3 % between the two time "
             "steps. The load partition (F / (p A_c) and the fluid's share) is explained in docs/model.md §8.</p>"]
    if summary is not None:
        parts.append(report.energy_box(summary))
    parts.append("<h2>Verdicts</h2>" + report.frame_table(verdicts(config, table)))
    for study, rows in table.groupby("study", sort=False):
        parts.append(f"<h2>{html.escape(config['studies'][study].get('title', study))}</h2>")
        parts.append(report.frame_table(readable(rows)))
    for study, rows in (compared or {}).items():
        parts.append(f"<h2>{html.escape(config['studies'][study].get('title', study))}</h2>")
        parts.append(report.frame_table(rows.rename(columns=dict(METRICS))))
    parts.append(report.figure_list(config, figure_files, here))
    report.write_page(path, f"cellsim {target}", parts)
