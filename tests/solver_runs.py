"""Running cellsim from tests: several cases side by side, one per core, and reading results."""
import concurrent.futures
import json
import os
import subprocess

import h5py
import numpy as np


def run_cases(cellsim, case_file, out_dir, cases, jobs=None):
    """cases: {name: {key: value}} overrides of case_file; returns {name: path of the result}."""
    jobs = jobs or max(1, os.cpu_count() or 1)

    def one(item):
        name, overrides = item
        out = out_dir / f"{name}.h5"
        cmd = [cellsim, "run", str(case_file), "-o", str(out), "--quiet"]
        for key, value in overrides.items():
            cmd += ["--set", f"{key}={json.dumps(value)}"]
        done = subprocess.run(cmd, capture_output=True, text=True)
        assert done.returncode == 0, f"{name}: exit {done.returncode}: {done.stderr}"
        return name, out

    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        return dict(pool.map(one, cases.items()))


def timeseries(path):
    """All /timeseries datasets of a result file as numpy arrays, plus its resolved case."""
    with h5py.File(path) as f:
        assert f.attrs["completed"] == 1
        series = {name: np.asarray(data) for name, data in f["timeseries"].items()}
        series["case"] = json.loads(f.attrs["case_json"])
    return series
