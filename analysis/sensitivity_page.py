"""The sensitivity target's page (results/report/sensitivity.html): what was run, the emulators' held-out
check, the Sobol table, the check of the slider page's setting against a full run, and the figures."""
import html
import pathlib

from analysis import html_page


def intro(config, study, frame, spec):
    factors = ", ".join(f"{html.escape(config['axes'][f]['title'])} {f_spec['range'][0]:g}-{f_spec['range'][1]:g}"
                        f"{' (log)' if f_spec.get('scale') == 'log' else ''}" for f, f_spec in spec["factors"].items())
    counts = frame["role"].value_counts()
    return (f"<h1>Global sensitivity of the closed cell</h1><p>{html.escape(config['studies'][study]['title'])}. "
            f"A scrambled Sobol design of {counts.get('train', 0)} runs over {factors}; {counts.get('held_out', 0)} "
            f"runs of a second sequence check the emulators. Every run is the closed cell (one pressure) in the dynamic "
            f"scheme at level 1, dried to steady state and compressed to strain 0.21 (config: studies.{study}). "
            f"Gaussian-process emulators (analysis/emulator.py) learn the stress at strains 0.02-0.20 and eps in "
            f"their logarithm, the dried V/V0 as it is. Indices are those of the emulator's mean; their intervals "
            f"come from emulators refitted on runs drawn with replacement.</p>"
            f"<p><a href='emulator.html'>The emulator in the browser</a>: a slider per factor, the predicted "
            f"stress-strain curve with its band (offline).</p>")


def write(path, config, study, frame, spec, checks, indices, check_point, figure_files):
    here = pathlib.Path(path).parent
    held = checks.rename(columns={"q2": "Q2", "rmse": "RMSE (emulated units)", "coverage_95": "share in 95 % band",
                                  "band_95_mean": "mean half-width of the 95 % band", "runs": "held-out runs"})
    table = indices.copy()
    table["factor"] = [config["axes"][f]["title"] for f in table["factor"]]
    parts = [intro(config, study, frame, spec),
             "<h2>The emulators on held-out runs</h2><p>Q2 = 1 - SS_res / SS_tot over runs the emulators never "
             "saw; RMSE in the emulated units (ln for the stress and eps: 0.1 is about 10 %).</p>",
             html_page.frame_table(held),
             "<h2>Sobol indices</h2><p>First order S_i (the variance of the answer explained by one factor alone) "
             "and total order S_Ti (with all its interactions), 95 % intervals; one_at_a_time: the factor's share of "
             "the variance along its own range with the others at the paper's baseline (X/X0 = 0.5), as the paper's "
             "one-at-a-time sweeps see it.</p>",
             html_page.frame_table(table),
             "<h2>The slider page's setting against a full run</h2><p>A setting inside the ranges that is no design "
             "point (studies." + html.escape(study) + ".design.check), run in full and predicted by the emulators.</p>",
             html_page.frame_table(check_point)]
    parts.append(html_page.untitled_figures(figure_files, here))
    html_page.write_page(path, "cellsim sensitivity", parts)
