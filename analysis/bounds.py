"""The rate and drainage bounds (config/converged.yaml, target converged_bounds: studies rate_bounds,
drainage and their slow end, bounds_slow_end): how far the paper's 1 m/s curves are from the quasi-static
limit, how much stiffer a closed cell is than one that lets water out while it is pressed, and which curve
a texture-analyser experiment should be compared with; and the texture analyser's own study (the report).
Stresses are the smoothed ones (the mean over +-0.01 strain, analysis/aggregate.py)."""
import html
import pathlib

import numpy as np
import pandas as pd

from analysis.aggregate import rows_of
from analysis import html_page, references
from analysis.html_page import figure_list, frame_table
from analysis.matrix import case_default

STRAINS = (0.05, 0.10)
QUASI_STATIC_TOLERANCE = 0.05  # the two slowest speeds within 5 %: the quasi-static limit
SPEED, LP = "compression.plate_speed_m_s", "compression.Lp_m_per_s_Pa"
REAL_LP = case_default(LP)      # m/(s Pa): the paper's compression L_p, a real cell's (model.md §5)
REFERENCE_STRAIN = 0.10         # the mass lost and the drainage time are read at this strain
# 1/s: nominal strain rates of texture-analyser tests on tissue, crosshead speeds of 0.1-20 mm/min on samples
# about 10 mm high (a cell in the tissue strains as fast as the tissue).
TEXTURE_ANALYSER_RATE = (1e-4, 3e-2)


def stress(row, strain):
    return row[f"smoothed_stress_kPa_at_{strain:.2f}"]


def quasi_static_table(summary, study="rate_bounds"):
    """Per dryness and strain: the stress at each plate speed (fastest first; empty where a case is
    missing) and the change between the two slowest speeds that ran."""
    rows = rows_of(summary, study)
    speeds = sorted(rows[SPEED].unique(), reverse=True)
    out = []
    for x in sorted(rows["dryness"].unique(), reverse=True):
        at_x = rows[np.isclose(rows["dryness"], x)]
        for strain in STRAINS:
            entry = {"X/X0": x, "strain": strain}
            for v in speeds:
                at_v = at_x[np.isclose(at_x[SPEED], v)]
                entry[f"{v:g} m/s [kPa]"] = stress(at_v.iloc[0], strain) if len(at_v) else np.nan
            values = [entry[f"{v:g} m/s [kPa]"] for v in speeds]
            reached = [value for value in values if np.isfinite(value)]
            change = reached[-1] / reached[-2] - 1 if len(reached) > 1 else np.nan
            entry["two slowest: change"] = change
            entry["quasi-static (< 5 %)"] = ("" if not np.isfinite(change) else
                                             "yes" if abs(change) < QUASI_STATIC_TOLERANCE else "no")
            out.append(entry)
    return pd.DataFrame(out)


def drained_table(summary, study="drainage"):
    """Per dryness and compression L_p: the stresses, their change against the sealed cell (the paper's
    L_p, 1e-12; empty if it did not run), and the share of the cell's water that left by strain 0.10."""
    rows = rows_of(summary, study)
    out = []
    for x in sorted(rows["dryness"].unique(), reverse=True):
        at_x = rows[np.isclose(rows["dryness"], x)].sort_values(LP)
        sealed = at_x[np.isclose(at_x[LP], REAL_LP, rtol=1e-9, atol=0)]
        for _, r in at_x.iterrows():
            entry = {"X/X0": x, "compression L_p [m/(s Pa)]": r[LP]}
            for strain in STRAINS:
                entry[f"stress at {strain:.2f} [kPa]"] = stress(r, strain)
                entry[f"change at {strain:.2f}"] = (stress(r, strain) / stress(sealed.iloc[0], strain) - 1
                                                    if len(sealed) else np.nan)
            entry[f"water lost by {REFERENCE_STRAIN:.2f} [%]"] = 100 * r[f"mass_lost_at_{REFERENCE_STRAIN:.2f}"]
            entry["drains like a real cell in [s]"] = real_drainage_time_s(r)
            out.append(entry)
    return pd.DataFrame(out)


def real_drainage_time_s(row):
    """The time over which a real cell (L_p = 1e-12) lets out the water this run let out by strain 0.10:
    Eq 11's flow is L_p x (P - P_T) x area, so the same water takes the run's time from the plates' start
    to strain 0.10 x L_p / 1e-12."""
    return row[f"compression_time_us_at_{REFERENCE_STRAIN:.2f}"] * 1e-6 * row[LP] / REAL_LP


def verdict_text(quasi_static, drained):
    """Which curve a texture-analyser experiment should be compared with, from the two tables."""
    parts = []
    if not quasi_static.empty:
        changes = quasi_static["two slowest: change"].dropna()
        slowest = min(float(c.split(" ")[0]) for c in quasi_static.columns if c.endswith("m/s [kPa]"))
        if len(changes) and (changes.abs() < QUASI_STATIC_TOLERANCE).all():
            parts.append(f"Between the two slowest plates the stress changes by at most {100 * changes.abs().max():.1f} % "
                         f"at every dryness and strain: the {slowest:g} m/s curves are the quasi-static limit to 5 %.")
        elif len(changes):
            worst = quasi_static.loc[changes.abs().idxmax()]
            parts.append(f"Between the two slowest plates the stress still changes by up to "
                         f"{100 * changes.abs().max():.1f} % (X/X0 = {worst['X/X0']:g}, strain {worst['strain']:.2f}): "
                         f"the {slowest:g} m/s curves are not yet quasi-static, and the quasi-static stress lies beyond "
                         f"them in the direction the slower plates move it.")
    if not drained.empty:
        parts.append(drainage_text(drained))
    return "".join(f"<p>{html.escape(p)}</p>" for p in parts)


def drainage_text(drained):
    """Which drained curve stands for a texture-analyser test: the one whose water would take a real cell
    as long to let out as such a test takes to reach strain 0.10."""
    lp_column, time_column = "compression L_p [m/(s Pa)]", "drains like a real cell in [s]"
    lost_column, change_column = f"water lost by {REFERENCE_STRAIN:.2f} [%]", f"change at {STRAINS[0]:.2f}"
    slow, fast = (REFERENCE_STRAIN / r for r in TEXTURE_ANALYSER_RATE)
    times = ", ".join(f"{t:.3g} s at L_p = {lp:g}" for lp, t in
                      drained.groupby(lp_column)[time_column].first().items())
    text = (f"A texture analyser takes tissue to strain {REFERENCE_STRAIN:.2f} in {fast:.2g}-{slow:.4g} s (nominal strain "
            f"rates {TEXTURE_ANALYSER_RATE[0]:g}-{TEXTURE_ANALYSER_RATE[1]:g} per second). Eq 11's flow is L_p x "
            f"overpressure x area, so a real cell (L_p = {REAL_LP:g}) lets out the water a run lets out by strain "
            f"{REFERENCE_STRAIN:.2f} over that run's compression time x L_p / {REAL_LP:g}: {times}. ")
    matching = drained[(drained[time_column] >= fast) & (drained[time_column] <= slow)]
    most = drained.loc[drained[lost_column].idxmax()]
    text += (f"The most drained cell lost {most[lost_column]:.2g} % of its water by strain {REFERENCE_STRAIN:.2f} "
             f"(X/X0 = {most['X/X0']:g})")
    if np.isfinite(most[change_column]):
        text += f", and its stress at strain {STRAINS[0]:.2f} changed by {100 * most[change_column]:+.0f} % against the closed cell"
    text += ". "
    if matching.empty:
        return text + ("None of the drained runs drains like a texture-analyser test; the curve to compare with lies "
                       "beyond the most drained one.")
    lps = ", ".join(f"{lp:g}" for lp in sorted(matching[lp_column].unique()))
    return text + (f"A texture-analyser experiment is therefore to be compared with the drained curves at L_p = {lps}, "
                   f"at the slowest plate's distance from the quasi-static limit (the drained runs are pressed at 1 m/s "
                   f"and keep the rate study's inertial part); the paper's closed cell is the undrained, dynamic bound.")


def section(config, summary):
    """The report's section on the bounds, or "" if the run has neither study."""
    studies = config["studies"]
    quasi_static = quasi_static_table(summary) if "rate_bounds" in studies else pd.DataFrame()
    drained = drained_table(summary) if "drainage" in studies else pd.DataFrame()
    if quasi_static.empty and drained.empty:
        return ""
    parts = ["<h2>Rate and drainage bounds</h2>",
             "<p>The paper's plates move at 1 m/s, 1e3-1e6 times faster than a texture analyser, and at that "
             "speed no water leaves a cell. These studies say how far the curves are from the slow and from the "
             "drained limit (config/converged.yaml; docs/model-closures.md).</p>"]
    if not quasi_static.empty:
        parts += ["<h3>Toward the quasi-static limit (study rate_bounds)</h3>", frame_table(quasi_static)]
    if not drained.empty:
        parts += ["<h3>Drained compression (study drainage)</h3>", frame_table(drained)]
    parts += ["<h3>Which curve to compare with a texture analyser</h3>", verdict_text(quasi_static, drained)]
    return "".join(parts)


def slow_end(summary, drained):
    """The quasi-static closed cell's stresses at STRAINS per dryness (study bounds_slow_end), closed or
    drained (compression L_p 1e-6): the bounds' slow end."""
    rows = rows_of(summary, "bounds_slow_end")
    rows = rows[np.isclose(rows[LP], 1e-6) == drained]
    return {float(r["dryness"]): [stress(r, e) for e in STRAINS] for _, r in rows.iterrows()}


def slow_end_table(summary):
    """Per dryness: the quasi-static closed cell, sealed and drained, at STRAINS [kPa]."""
    sealed, drained = slow_end(summary, False), slow_end(summary, True)
    out = []
    for x in sorted(set(sealed) | set(drained), reverse=True):
        entry = {"X/X0": x}
        for name, values in (("sealed", sealed), ("drained (L_p 1e-6)", drained)):
            for k, e in enumerate(STRAINS):
                entry[f"quasi-static, {name}, at {e:.2f} [kPa]"] = values[x][k] if x in values else np.nan
        out.append(entry)
    return pd.DataFrame(out)


def write_page(path, config, summary, figure_files):
    """The converged_bounds target's page: the two bounds' tables, their quasi-static slow end, which
    curve a texture analyser should be compared with, and the figures."""
    here = pathlib.Path(path).parent
    parts = [section(config, summary)]
    slow = slow_end_table(summary)
    if not slow.empty:
        parts += ["<h3>Their slow end: the closed cell, quasi-static (study bounds_slow_end)</h3>",
                  "<p>One uniform pressure per cell at equilibrium at every plate step (K 20 MPa, the SPH cells'): "
                  "what the rate study's curves tend to as the plate slows, sealed and drained.</p>", frame_table(slow)]
    parts.append(figure_list(config, figure_files, here))
    html_page.write_page(path, "cellsim: rate and drainage bounds", parts)


TEXTURE_STUDY = "texture_analyser"


def texture_table(config, summary, root="."):
    """The texture analyser's study (slow and drained: the closed cell quasi-static at water's K, L_p 1e-6)
    per wall and dryness, beside the apple references of its figure: stresses at STRAINS [kPa] and the
    apparent modulus over strains 0.01-0.05 [MPa]."""
    rows = rows_of(summary, TEXTURE_STUDY)
    out = [{"case": f"{r['wall_bending']} wall, X/X0 = {r['dryness']:g}",
            **{f"stress at {e:.2f} [kPa]": stress(r, e) for e in STRAINS},
            "modulus 0.01-0.05 [MPa]": r.get("modulus_MPa_nominal", np.nan)}
           for _, r in rows.sort_values(["wall_bending", "dryness"], ascending=[True, False]).iterrows()]
    figures = [spec for spec in config["figures"].values() if spec["study"] == TEXTURE_STUDY]
    for name in (figures[0].get("references", []) if figures else []):
        ref = config["references"][name]
        strain, stress_kPa = references.load(ref, root)
        out.append({"case": ref["label"], **{f"stress at {e:.2f} [kPa]": float(np.interp(e, strain, stress_kPa))
                                            for e in STRAINS},
                    "modulus 0.01-0.05 [MPa]": ref.get("initial_modulus_MPa", np.nan)})
    return pd.DataFrame(out)


def texture_section(config, summary, root="."):
    """The report's section for a user with a texture analyser, or "" without the study."""
    if TEXTURE_STUDY not in config["studies"] or rows_of(summary, TEXTURE_STUDY).empty:
        return ""
    return ("<h2>For a texture analyser: slow and drained (study texture_analyser)</h2>"
            "<p>A texture analyser presses tissue over seconds, so its cells are at equilibrium and let water out "
            "(docs/model-closures.md, 'Which curve stands for a texture-analyser test'). These cases are that limit: "
            "the closed cell quasi-static at water's K, its compression L_p 1e-6 (a million times the paper's), the "
            "paper's wall and the wall that bends like its 6 um, fresh and dried. Beside them the apple tissue "
            "references of their figure. A single cell between plates is not tissue (the tissue page): read the "
            "difference as a bound, not as a fit.</p>" + frame_table(texture_table(config, summary, root)))
