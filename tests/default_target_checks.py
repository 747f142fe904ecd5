"""What a run of the default target must hold, whichever matrix it ran (the CI study, the tiny matrix):
its 18 figures each showing their data, tables with every case and parameter, the report with every
figure and every claim. The tests of each run add what is particular to its matrix."""
import re

import pandas as pd

from analysis import matrix
from conftest import workflow_config
from figure_checks import check_figures

SUMMARY_COLUMNS = ["dryness", "turgor_kPa", "plate_speed_m_s", "G_MPa", "t0_um", "D_um", "cell.n_wall",
                   "drying.dryness", "stress_kPa_at_0.05", "dried_V_over_V0", "peak_force_top_uN",
                   "drying_steady", "drying_steady_time_us", "settle_iterations", "warning"]


def check_default_figures(root, configs, out, tmp_path):
    """The default target's 18 figures, each what its spec asks; no other target's drawn."""
    config = workflow_config(root, configs, out)
    figures = matrix.target_figures(config)
    assert len(figures) == 18  # the paper's; the other targets' are not drawn by default
    check_figures(config, out, root, tmp_path, figures)
    assert not any(out.glob("figures/conv*")) and not any(out.glob("figures/tis*"))


def check_tables(out, cases):
    """summary.csv, timeseries.csv and the manifest hold exactly `cases`, with every parameter and
    summary column and a stress at strain 0.05 for each; returns the summary."""
    summary = pd.read_csv(out / "tables" / "summary.csv")
    assert set(summary["case"]) == set(cases)
    for column in SUMMARY_COLUMNS:
        assert column in summary.columns, column
    assert summary["stress_kPa_at_0.05"].notna().all()
    series = pd.read_csv(out / "tables" / "timeseries.csv", usecols=["case", "stage", "plate_stress_Pa"])
    assert set(series["case"]) == set(summary["case"])
    assert (series["stage"] == 1).any() and (series["stage"] == 0).any()
    assert set(pd.read_csv(out / "manifest.csv")["case"]) == set(summary["case"])
    return summary


def report_claims(out):
    """The report shows the 18 figures and the model closures; returns its 16 claims (claims.csv)."""
    html = (out / "report" / "index.html").read_text()
    for k in range(1, 19):
        assert f"figures/fig{k:02d}.png" in html
    assert "Model closures" in html and "wall-pressure closure" in html
    claims = pd.read_csv(out / "tables" / "claims.csv")
    assert len(claims) == 16
    # The findings come first, this run's counted from its own claims table, and the header names the code.
    assert html.index("<h2>Findings</h2>") < html.index("<h2>The paper's claims and this run</h2>")
    counted = ", ".join(f"{n} {v}" for v, n in claims["verdict"].value_counts().reindex(
        ["agree", "disagree", "not reached", "not run"]).dropna().astype(int).items() if n)
    assert f"The paper's 16 claims: {counted}" in html
    assert re.search(r"Made by cellsim \d+\.\d+\.\d+, commit [0-9a-f]{12}", html)
    return claims
