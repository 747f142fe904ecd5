"""The regression cases: run them and reduce each to the quantities that are compared."""
import json
import pathlib
import tempfile

from analysis.aggregate import summarise
from analysis.results import timeseries
from solver_runs import run_cases

HERE = pathlib.Path(__file__).parent / "regression"


def spec():
    return json.loads((HERE / "cases.json").read_text())


def measure(cellsim, out_dir=None):
    """{case: {quantity: value}} for every regression case."""
    s = spec()
    out_dir = pathlib.Path(out_dir or tempfile.mkdtemp(prefix="regression-"))
    case_file = out_dir / "base.json"
    case_file.write_text(json.dumps(s["base"]))
    paths = run_cases(cellsim, case_file, out_dir, s["cases"])
    results = {}
    for name, path in paths.items():
        ts = timeseries(path)
        metrics = summarise(ts)
        metrics["end_volume_um3"] = ts["volume_m3"].iloc[-1] * 1e18
        metrics["end_area_um2"] = ts["area_m2"].iloc[-1] * 1e12
        results[name] = {q: float(metrics[q]) for q in s["tolerances"]}
    return results
