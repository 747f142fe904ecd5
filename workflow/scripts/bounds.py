"""Snakemake script: the page of the rate and drainage bounds (target converged_bounds)."""
import pandas as pd

import _path  # noqa: F401
from analysis import bounds, matrix

sm = snakemake  # noqa: F821 (provided by Snakemake)
config = sm.config
figures = {f: f"{config['output_dir']}/figures/{f}.png" for f in matrix.target_figures(config, "converged_bounds")}
bounds.write_page(sm.output.html, config, pd.read_csv(sm.input.summary), figures)
