"""Snakemake script: the sensitivity target's emulators, held-out check, Sobol table, check point, figures,
page and slider page (analysis/sensitivity.py)."""
import json
import pathlib

import numpy as np
import pandas as pd

import _path  # the analysis package importable; the rule's files by name
from analysis import emulator, emulator_page, provenance, sensitivity, sensitivity_page
from analysis.design_runs import STRAINS, STRESS_OUTPUTS
from analysis.figures import common
from analysis.figures import sensitivity as figures

sm = snakemake  # noqa: F821 (provided by Snakemake)
config, study = sm.config, sm.params.study
spec = config["studies"][study]["design"]
frame = pd.read_csv(sm.input.table)
columns = list(sensitivity.ANSWERS) + [c for c in STRESS_OUTPUTS if c not in sensitivity.ANSWERS]
print(f"sensitivity: fitting {len(columns)} emulators on {int((frame['role'] == 'train').sum())} runs", flush=True)
emulators = sensitivity.fit_all(frame, spec, columns)
checks = sensitivity.held_out_table(frame, spec, emulators)
checks.to_csv(sm.output.held_out, index=False)
print(checks.to_string(index=False), flush=True)
print(f"sensitivity: Sobol indices, {sensitivity.BOOTSTRAP} bootstrap emulators per answer", flush=True)
indices = sensitivity.sobol_table(config, frame, spec, emulators)
indices.to_csv(sm.output.indices, index=False)
print(indices.to_string(index=False), flush=True)

check_run = frame[frame["role"] == "check"].iloc[0]
curve = sensitivity.predicted_curve(spec, emulators, {f: check_run[f] for f in spec["factors"]})
curve["run_kPa"] = [check_run[c] for c in STRESS_OUTPUTS]
curve["inside_band"] = (curve["run_kPa"] >= curve["low_kPa"]) & (curve["run_kPa"] <= curve["high_kPa"])
curve.to_csv(sm.output.check_point, index=False)
print(curve.to_string(index=False), flush=True)

for name, figure in (("sensitivity_indices", figures.draw_indices(config, indices, sensitivity.ANSWERS)),
                     ("sensitivity_held_out", figures.draw_held_out(frame, spec, emulators, sensitivity.ANSWERS, checks))):
    common.save(figure, getattr(sm.output, f"{name}_png"), getattr(sm.output, f"{name}_pdf"))

emulator_page.write(sm.output.emulator_page, sm.output.emulator_data, sensitivity.page_data(config, study, spec, emulators),
                    provenance.line())
pathlib.Path(sm.output.emulators).write_text(json.dumps(
    {"study": study, "strains": list(STRAINS), "emulators": {c: emulator.as_json(em) for c, em in emulators.items()}}))
sensitivity_page.write(sm.output.html, config, study, frame, spec, checks, indices, curve,
                       {"sensitivity_indices": sm.output.sensitivity_indices_png,
                        "sensitivity_held_out": sm.output.sensitivity_held_out_png})
if not np.isfinite(indices[["first", "total"]].to_numpy()).all():
    raise SystemExit("sensitivity: an index is not finite; see the tables above")
