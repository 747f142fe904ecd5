"""Snakemake script: the claims table and the HTML report."""
import pandas as pd

import _path  # noqa: F401
from analysis import claims, matrix, report

sm = snakemake  # noqa: F821 (provided by Snakemake)
config = sm.config
cases = matrix.expand(config)
summary = pd.read_csv(sm.input.summary)
series = pd.read_csv(sm.input.timeseries, usecols=claims.SERIES_COLUMNS)
base = {axis: matrix.get_key(config["base"], spec["key"]) for axis, spec in config["axes"].items()}
rows = claims.evaluate(summary, base, series)
pd.DataFrame(rows).to_csv(sm.output.claims, index=False)
figures = {f: f"{config['output_dir']}/figures/{f}.png" for f in config["figures"]}
report.write(sm.output.html, config, cases, summary, rows, figures, _path.ROOT, cell_pages=sm.input.cells)
