"""Snakemake script: the calibrate target's posterior (analysis/calibration.py): emulators of the targets'
columns judged on held-out runs, the posterior by MCMC and its diagnostics, the predictive, the recovery of a
held-out run's parameters, and the figures."""
import json
import pathlib
import sys

import numpy as np
import pandas as pd

import _path  # the analysis package importable; the rule's files by name
from analysis import calibration, design, design_runs, emulator
from analysis.figures import calibration as figures
from analysis.figures import common
from analysis.matrix import base_value

sm = snakemake  # noqa: F821 (provided by Snakemake)
config = sm.config
try:
    spec, unknowns, targets = calibration.check(config)
except calibration.CalibrationError as error:
    sys.exit(f"calibrate: {error}")
study = config["calibration"]["study"]
factors = list(spec["factors"])
several = [a for a, v in config["studies"][study]["vary"].items() if len(v) > 1]
wide = design_runs.wide_by(pd.read_csv(sm.input.table), factors, several)
columns = sorted({t[1] for t in targets})
wide = design_runs.finite(wide, columns)
train, held = wide[wide["role"] == "train"], wide[wide["role"] == "held_out"]
x_train, x_held = design.unit_matrix(train, spec), design.unit_matrix(held, spec)
emulators = {c: emulator.fit(x_train, train[c].to_numpy(), "none" if c.startswith("dried_V_over_V0") else "log")
             for c in columns}
try:
    judged = calibration.judge_emulators(emulators, held, x_held, targets)
except calibration.CalibrationError as error:
    sys.exit(f"calibrate: {error}")
# The likelihood's emulator error: each emulator's sd widened until its held-out runs sit at one sd.
emulators = {c: emulator.widened_to_held_out(em, x_held, held[c].to_numpy()) for c, em in emulators.items()}
judged["sd_scale"] = [emulators[c]["sd_scale"] for c in judged["column"]]
judged.to_csv(sm.output.judged, index=False)
pathlib.Path(sm.output.emulators).write_text(json.dumps({c: emulator.as_json(em) for c, em in emulators.items()}))
print(judged.to_string(index=False), flush=True)

sampler = config["calibration"].get("sampler", {})
log_posterior = calibration.log_posterior_function(emulators, targets, factors, unknowns)
print(f"calibrate: sampling ({sampler.get('walkers', 32)} walkers x {sampler.get('steps', 3000)} steps)", flush=True)
flat, diagnostics = calibration.sample(log_posterior, len(unknowns), sampler)
samples = calibration.to_values(flat, unknowns, spec["factors"])
table = calibration.posterior_table(samples, unknowns, spec["factors"])
baseline = {u: base_value(config, u) for u in unknowns}  # config base: the paper's wall (c = 0.4 is ours)
table["baseline"] = [baseline[u] for u in unknowns]
table["baseline_quantile"] = [float(np.mean(samples[u] <= baseline[u])) for u in unknowns]
table.to_csv(sm.output.posterior, index=False)
samples.to_csv(sm.output.samples, index=False)
print(table.to_string(index=False), flush=True)
pathlib.Path(sm.output.diagnostics).write_text(json.dumps(diagnostics, indent=1))
print(json.dumps(diagnostics), flush=True)
predictive = calibration.predictive(emulators, targets, flat, unknowns, factors)
predictive["scale"] = [t[4] for t in targets]
predictive.to_csv(sm.output.predictive, index=False)
print(predictive.to_string(index=False), flush=True)

# Recovery: the first held-out run's answers, with the targets' noise added, as if measured; its own
# parameters should lie inside the posterior's 90 % interval.
rng = np.random.default_rng(sampler.get("seed", 1))
run = held.iloc[0]
made = []
for name, column, _value, sigma, scale in targets:
    noisy = run[column] * np.exp(sigma * rng.standard_normal()) if scale == "log" else run[column] + sigma * rng.standard_normal()
    made.append((name, column, float(noisy), sigma, scale))
recovered_flat, recovery_diagnostics = calibration.sample(calibration.log_posterior_function(emulators, made, factors, unknowns),
                                       len(unknowns), sampler)
recovered = calibration.posterior_table(calibration.to_values(recovered_flat, unknowns, spec["factors"]), unknowns,
                                        spec["factors"])
recovered["truth"] = [run[u] for u in unknowns]
recovered["inside_90"] = (recovered["p05"] <= recovered["truth"]) & (recovered["truth"] <= recovered["p95"])
recovered["chain_steps"] = recovery_diagnostics["steps"]
recovered["kept_over_autocorrelation"] = recovery_diagnostics["kept_over_autocorrelation"]
recovered.to_csv(sm.output.recovery, index=False)
print(recovered.to_string(index=False), flush=True)

labels = {name: f"{name}\n({target['quantity']} at {', '.join(f'{a} {v:g}' for a, v in target.get('where', {}).items())})"
          for name, target in config["calibration"]["targets"].items()}
common.save(figures.draw_posterior(config, samples, unknowns, spec["factors"], baseline),
            sm.output.posterior_png, sm.output.posterior_pdf)
common.save(figures.draw_predictive(predictive, wide, labels), sm.output.predictive_png, sm.output.predictive_pdf)
