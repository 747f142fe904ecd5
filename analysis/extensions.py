"""The extensions target's tables and page (`snakemake --cores 2 extensions`, docs/model.md §3b-§3c): the
load-unload loops of the elastic and the elastic-plastic wall (permanent set, dissipated energy, the
plastic flow's share), and the seeded heterogeneous ensembles (mean and band, the claims on the mean,
how the band grows with the properties' spread)."""
import pathlib

import numpy as np
import pandas as pd

from analysis import ensembles, html_page
from analysis.aggregate import rows_of


def load_unload_table(summary, study="load_unload"):
    """One row per loop: dryness, wall law, the loading's stresses and peak force, the permanent set, the
    energy the loop dissipated (the plate's net work) and the plastic flow's part of it."""
    out = []
    for _, r in rows_of(summary, study).sort_values(["dryness", "wall_law"], ascending=[False, True]).iterrows():
        dissipated, plastic = r["loop_dissipated_nJ"], r["loop_plastic_loss_nJ"]
        out.append({"X/X0": r["dryness"], "wall": r["wall_law"],
                    "stress at 0.05 [kPa]": r["smoothed_stress_kPa_at_0.05"],
                    "stress at 0.10 [kPa]": r["smoothed_stress_kPa_at_0.10"],
                    "peak force [uN]": r["peak_force_top_uN"], "unloaded from": r["strain_reached"],
                    "permanent set": r["unload_permanent_set"], "loop dissipated [nJ]": dissipated,
                    "by plastic flow [nJ]": plastic,
                    "plastic share": plastic / dissipated if dissipated else np.nan,
                    "plastic strain, dried (mean)": r["dried_plastic_strain_mean"],
                    "plastic strain, end (mean)": r["end_plastic_strain_mean"]})
    return pd.DataFrame(out)


def tables(config, summary, series):
    """{name: frame} of the page's tables (also written as CSV); a table whose study the config no longer
    has is empty."""
    studies = config["studies"]
    reference = rows_of(summary, "ensemble_reference")
    has = lambda study: study in studies and not rows_of(summary, study).empty  # noqa: E731
    return {"load_unload": load_unload_table(summary) if has("load_unload") else pd.DataFrame(),
            "ensemble": ensembles.ensemble_table(config, summary, "ensemble", reference) if has("ensemble")
            else pd.DataFrame(),
            "ensemble_claims": ensembles.ensemble_claims(config, summary, series, "ensemble", reference)
            if has("ensemble") else pd.DataFrame(),
            "band_growth": ensembles.band_growth(config, summary) if has("ensemble_spread") else pd.DataFrame()}


INTRO = ("<h1>The paper's two named extensions: an elastic-plastic wall, and heterogeneous properties</h1>"
         "<p>Both with the paper's configuration (the Lennard-Jones coupling at the paper's resolution; the "
         "convergence page says how far its curves are from resolution-independent beyond strain 0.05). "
         "docs/model.md §3b-§3c give the laws and where their numbers come from.</p>")

def loop_text(summary, study="load_unload"):
    """What the loops ran, from their cases: speeds, turn, yield stress and hardening."""
    rows = rows_of(summary, study)
    if rows.empty:
        return "<p>No load-unload study ran.</p>"
    plastic = rows[rows["wall.yield_stress_MPa"].notna()]
    values = lambda column, of=rows: ", ".join(f"{v:g}" for v in sorted(of[column].dropna().unique()))  # noqa: E731
    return (f"<p>The top plate loads each cell at {values('compression.plate_speed_m_s')} m/s to strain "
            f"{values('compression.unload_at_strain')} and returns at {values('compression.unload_speed_m_s')} m/s; "
            "the run ends when the cell leaves the plate, and the strain then is the permanent set. The loop's "
            "dissipated energy is the plate's net work over it (the loop's area); 'by plastic flow' is what the "
            "wall's sliders took (the rest went to the fluid's viscosity and the bonds' damping, Eqs 4 and 16, or "
            f"stays in the deformed cell). The elastic-plastic wall yields at {values('wall.yield_stress_MPa')} MPa "
            f"and hardens by {values('wall.hardening_MPa', plastic)} MPa per unit plastic strain (numbers "
            "assumed: docs/model.md §3b). A dried elastic cell recovers slowly: part of its 'set' is a recovery "
            "slower than the plate's return.</p>")


ENSEMBLE_TEXT = ("<p>Each member draws its bonds' G and t0 and its fluid's viscosity from lognormal "
                 "distributions of mean 1 and the coefficient of variation given (the <code>spread</code> axis in "
                 "config/config.yaml, which also sets how far the wall's draws are correlated); the members are "
                 "the study's seeds. Numbers are the members' mean and their 10th-90th percentile band; "
                 "'homogeneous' is the paper's uniform cell at the same dryness. The claims below are judged on the "
                 "ensemble's mean curves, with the same measure on each seed's pair of cells as the band. The "
                 "spread 1e-06 is a control: cells that differ by a millionth part by the dynamics alone.</p>")


def table(frame):
    return html_page.frame_table(frame) if len(frame) else "<p>(Its study is not in this run's config.)</p>"


def write_page(path, config, frames, figure_files, summary):
    here = pathlib.Path(path).parent
    parts = [INTRO, "<h2>Load-unload: elastic and elastic-plastic walls</h2>", loop_text(summary),
             table(frames["load_unload"]),
             "<h2>Heterogeneous cells: mean and band</h2>", ENSEMBLE_TEXT, table(frames["ensemble"]),
             "<h3>The paper's claims on the ensemble's mean</h3>", table(frames["ensemble_claims"]),
             "<h3>How the band grows with the spread of the properties (fresh cells)</h3>",
             table(frames["band_growth"]),
             html_page.figure_list(config, figure_files, here)]
    html_page.write_page(path, "cellsim extensions", parts)
