"""The calibrate target's page (results/report/calibrate.html): the targets with their provenance, the
emulators' held-out check against each target's uncertainty, the posterior and its diagnostics, the
predictive beside the data, the run at the median, the recovery of a held-out run, and the figures."""
import html
import json
import pathlib

import pandas as pd

from analysis import html_page


def targets_table(config):
    rows = []
    for name, t in config["calibration"]["targets"].items():
        rows.append({"target": name, "quantity": t["quantity"],
                     "where": ", ".join(f"{a} = {v:g}" for a, v in t.get("where", {}).items()),
                     "value": t["value"], "uncertainty": (f"sd {t['sigma']}" if "sigma" in t else f"sd of ln {t['sigma_ln']}"),
                     "provenance": t["provenance"]})
    return pd.DataFrame(rows)


def verdicts(config, posterior):
    """A sentence per unknown: its median and 90 % interval against the baseline's value (config base: the
    paper's wall; its c is ours)."""
    items = []
    for _, r in posterior.iterrows():
        title = html.escape(config["axes"][r["unknown"]]["title"])
        items.append(f"<li><b>{title}</b>: median {r['median']:.3g}, 90 % in {r['p05']:.3g}-{r['p95']:.3g} (prior "
                     f"{r['prior_low']:g}-{r['prior_high']:g}); the baseline's {r['baseline']:g} is {r['baseline'] / r['median']:.3g} "
                     f"times the median and lies at or above {100 * r['baseline_quantile']:.1f} % of the posterior.</li>")
    return "<ul>" + "".join(items) + "</ul>"


def write(path, config, tables, diagnostics, figure_files):
    here = pathlib.Path(path).parent
    study = config["calibration"]["study"]
    d = diagnostics
    tau = ", ".join(f"{t:.0f}" for t in d["autocorrelation_steps"])
    parts = [f"<h1>Calibration of the wall against measured numbers</h1><p>The posterior of "
             f"{html.escape(', '.join(config['calibration']['unknowns']))} (uniform priors over the ranges of "
             f"studies.{html.escape(study)}.design, in the log for log-scale factors), by MCMC (emcee) on Gaussian-"
             f"process emulators of the design's runs; each target's likelihood is widened by its emulator's own "
             f"uncertainty there (analysis/calibration.py). Change the targets in config (calibration.targets) and "
             f"run <code>snakemake --cores 2 calibrate</code> again (docs/extending.md).</p>",
             "<h2>The targets</h2>", html_page.frame_table(targets_table(config)),
             "<h2>The emulators against the targets' uncertainty</h2><p>Each emulator's rms error on the design's "
             "held-out runs, in the target's units (ln where the target is given by sigma_ln), must be below the "
             "target's sd, or the calibration stops. sd_scale: how much the emulator's sd is widened in the "
             "likelihood so that its held-out runs sit at one sd on average (1: not widened).</p>", html_page.frame_table(tables["judged"]),
             "<h2>The posterior</h2><p>Median and 5-95 % interval; baseline: config's base, the paper's wall (c = 0.4 is "
             "ours); baseline_quantile: where it lies in "
             "the posterior (the share of samples below it).</p>", verdicts(config, tables["posterior"]),
             html_page.frame_table(tables["posterior"]),
             f"<p>The chains: {d['walkers']} walkers x {d['steps']} steps ({d['steps_asked']} asked, run on while "
             f"shorter than 50 autocorrelation times), the first {d['burn']} dropped; acceptance "
             f"{d['acceptance_mean']:.2f} on average (lowest walker {d['acceptance_min']:.2f}); integrated "
             f"autocorrelation times {tau} steps, the kept chain {d['kept_over_autocorrelation']:.0f} times the "
             f"longest (emcee asks for more than 50), about {d['independent_samples']:.0f} independent samples.</p>",
             "<h2>The posterior predictive beside the data</h2>", html_page.frame_table(tables["predictive"]),
             "<h2>A full run at the posterior's median</h2><p>The design's case with its unknowns at their medians, "
             "run by the solver, beside the emulator's prediction there (95 % band) and the measured value.</p>",
             html_page.frame_table(tables["confirm"]),
             "<h2>Recovery of a held-out run's parameters</h2><p>The first held-out run's answers, with each "
             "target's noise added, calibrated as if measured: are its own parameters inside the 90 % interval?</p>",
             html_page.frame_table(tables["recovery"]), html_page.untitled_figures(figure_files, here)]
    parts.append(f"<details><summary>The chains' diagnostics as numbers</summary><pre>{html.escape(json.dumps(d, indent=1))}"
                 f"</pre></details>")
    html_page.write_page(path, "cellsim calibration", parts)
