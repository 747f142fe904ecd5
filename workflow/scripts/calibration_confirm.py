"""Snakemake script: one full run at the posterior's median for each moisture level the targets name (the
same case as the design's, its unknowns at their medians), beside the emulator's prediction there and the
measured value."""
import json
import pathlib
import subprocess

import numpy as np
import pandas as pd

import _path  # the analysis package importable; the rule's files by name
from analysis import calibration, design, design_runs, emulator, matrix

sm = snakemake  # noqa: F821 (provided by Snakemake)
config = sm.config
spec, unknowns, targets = calibration.check(config)
study = config["calibration"]["study"]
median = pd.read_csv(sm.input.posterior).set_index("unknown")["median"].to_dict()
emulators = {c: emulator.from_json(n) for c, n in json.loads(pathlib.Path(sm.input.emulators).read_text()).items()}
folder = pathlib.Path(sm.output.folder)
folder.mkdir(parents=True, exist_ok=True)
compressed = any(t["quantity"] == "stress_kPa" for t in config["calibration"]["targets"].values())
rows = []
for name, target in config["calibration"]["targets"].items():
    where = target.get("where", {})
    fixed = {axis: values[0] for axis, values in config["studies"][study]["vary"].items() if len(values) == 1}
    case, _values = matrix.study_case(config, config["studies"][study], {**fixed, **median, **where})
    tag = "_".join(f"{a}{v:g}" for a, v in sorted(where.items())) or "base"
    case_file, result = folder / f"median_{tag}.json", folder / f"median_{tag}.h5"
    case_file.write_text(matrix.case_json(case))
    extra = [] if compressed else ["--set", "compression.steps=0"]
    print(f"calibrate: the full run at the median, {tag}", flush=True)
    subprocess.run([sm.input.exe, "run", str(case_file), "-o", str(result), "--quiet", *extra], check=True)
    ran = design_runs.outputs(result, compressed)
    for _name, column, value, sigma, scale in [t for t in targets if t[0] == name]:
        em = emulators[column]
        u = np.array([[design.factor_to_unit(median[f], spec["factors"][f]) for f in spec["factors"]]])
        mean, sd = emulator.predict(em, u)
        rows.append({"target": name, "column": column, "measured": value,
                     "emulator_at_median": float(emulator.backward(mean[0], em["transform"])),
                     "emulator_p025": float(emulator.backward(mean[0] - emulator.Z95 * sd[0], em["transform"])),
                     "emulator_p975": float(emulator.backward(mean[0] + emulator.Z95 * sd[0], em["transform"])),
                     "run_at_median": ran[column.split("@")[0]], **{f"median_{u}": median[u] for u in unknowns}})
table = pd.DataFrame(rows)
table["run_inside_emulator_band"] = (table["run_at_median"] >= table["emulator_p025"]) & (
    table["run_at_median"] <= table["emulator_p975"])
table.to_csv(sm.output.table, index=False)
print(table.to_string(index=False), flush=True)
pathlib.Path(folder / "median.json").write_text(json.dumps(median, indent=1))
