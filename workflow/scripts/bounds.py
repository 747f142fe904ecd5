"""Snakemake script: the page of the rate and drainage bounds (target converged_bounds)."""
import pandas as pd

import _path  # the analysis package importable; the rule's files by name
from analysis import bounds

sm = snakemake  # noqa: F821 (provided by Snakemake)
config = sm.config
figures = _path.by_name(sm.input.figures)  # the rule's, in its order
bounds.write_page(sm.output.html, config, pd.read_csv(sm.input.summary), figures)
