"""Snakemake script: tidy tables of every run."""
import pathlib

import _path  # noqa: F401
from analysis import aggregate, matrix

sm = snakemake  # noqa: F821 (provided by Snakemake)
cases = matrix.expand(sm.config)
runs = [(cases[pathlib.Path(p).stem], p) for p in sm.input.runs]
series, summary = aggregate.tables(runs)
series.to_csv(sm.output.timeseries, index=False)
summary.to_csv(sm.output.summary, index=False)
