"""Snakemake script: the claims table and the HTML report."""
import pandas as pd

import _path  # the analysis package importable; the rule's files by name
from analysis import claims, columns, matrix, numerical_band, provenance, report

sm = snakemake  # noqa: F821 (provided by Snakemake)
config = sm.config
every_case = matrix.expand(config)
cases = {name: every_case[name] for name in matrix.target_cases(config, every_case)}  # the default target's
summary = pd.read_csv(sm.input.summary)
series = pd.read_csv(sm.input.timeseries, usecols=claims.SERIES_COLUMNS)
base = {axis: matrix.base_value(config, axis) for axis in config["axes"]}
rows = claims.evaluate(summary, base, series)
band = numerical_band.for_run(config, _path.ROOT)  # the LJ ladder, where this run is its level 1
for row in rows if band is not None else []:
    row["level_1_to_2"] = numerical_band.claim_band(band, row["figure"], config)
pd.DataFrame(rows).to_csv(sm.output.claims, index=False)
column_rows = columns.evaluate(config, summary, series, base)  # {} without claim_columns
columns.long_table(column_rows).to_csv(sm.output.columns, index=False)
provenance.write(sm.output.provenance)
figures = _path.by_name(sm.input.figures)  # the rule's, in its order
report.write(sm.output.html, config, cases, summary, rows, figures, _path.ROOT, cell_pages=sm.input.cells,
             column_rows=column_rows, band=band)
