"""Snakemake script: the extensions target's tables (CSV) and page (HTML)."""
import pathlib

import pandas as pd

import _path  # noqa: F401
from analysis import extensions, matrix

sm = snakemake  # noqa: F821 (provided by Snakemake)
config = sm.config
summary, series = pd.read_csv(sm.input.summary), pd.read_csv(sm.input.timeseries)
frames = extensions.tables(config, summary, series)
folder = pathlib.Path(sm.output.tables)
folder.mkdir(parents=True, exist_ok=True)
for name, frame in frames.items():
    frame.to_csv(folder / f"{name}.csv", index=False)
figures = {f: f"{config['output_dir']}/figures/{f}.png" for f in matrix.target_figures(config, "extensions")}
extensions.write_page(sm.output.html, config, frames, figures, summary)
