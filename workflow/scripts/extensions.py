"""Snakemake script: the extensions target's tables (CSV) and page (HTML)."""
import pathlib

import pandas as pd

import _path  # the analysis package importable; the rule's files by name
from analysis import extensions

sm = snakemake  # noqa: F821 (provided by Snakemake)
config = sm.config
summary, series = pd.read_csv(sm.input.summary), pd.read_csv(sm.input.timeseries)
frames = extensions.tables(config, summary, series)
folder = pathlib.Path(sm.output.tables)
folder.mkdir(parents=True, exist_ok=True)
for name, frame in frames.items():
    frame.to_csv(folder / f"{name}.csv", index=False)
figures = _path.by_name(sm.input.figures)  # the rule's, in its order
extensions.write_page(sm.output.html, config, frames, figures, summary)
