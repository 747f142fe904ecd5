"""Snakemake script: the LJ ladder's table (levels 1-3 at three dryness levels), printed and written."""
import pathlib

import _path  # noqa: F401
from analysis import aggregate, matrix, numerical_band

sm = snakemake  # noqa: F821 (provided by Snakemake)
cases = matrix.expand(sm.config)
runs = [(cases[pathlib.Path(p).stem], p) for p in sm.input.runs]
table = numerical_band.ladder_table(aggregate.tables(runs)[1])
table.to_csv(sm.output.table, index=False)
print(table.to_string(index=False))
for low, high in ((1, 2), (2, 3)):
    print(numerical_band.sentence(table, list(numerical_band.QUANTITIES), low, high))
