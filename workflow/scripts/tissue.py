"""Snakemake script: a tissue target's table (CSV) and page (HTML); the target is the rule's wildcard."""
import pandas as pd

import _path  # the analysis package importable; the rule's files by name
from analysis import tissue

sm = snakemake  # noqa: F821 (provided by Snakemake)
config, target = sm.config, sm.wildcards.target
summary, series = pd.read_csv(sm.input.summary), pd.read_csv(sm.input.timeseries)
runs = _path.by_name(sm.input.runs)  # the target's cases, in the rule's order
frame = tissue.table(config, summary, series, runs, target)
frame.to_csv(sm.output.table, index=False)
figures = _path.by_name(sm.input.figures)
tissue.write_page(sm.output.html, config, frame, figures, target, summary)
