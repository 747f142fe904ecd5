"""Snakemake script: a tissue target's table (CSV) and page (HTML); the target is the rule's wildcard."""
import pandas as pd

import _path  # noqa: F401
from analysis import matrix, tissue

sm = snakemake  # noqa: F821 (provided by Snakemake)
config, target = sm.config, sm.wildcards.target
summary, series = pd.read_csv(sm.input.summary), pd.read_csv(sm.input.timeseries)
cases = matrix.expand(config)
runs = {name: f"{config['output_dir']}/runs/{name}.h5" for name in matrix.target_cases(config, cases, target)}
frame = tissue.table(config, summary, series, runs, target)
frame.to_csv(sm.output.table, index=False)
figures = {f: f"{config['output_dir']}/figures/{f}.png" for f in matrix.target_figures(config, target)}
tissue.write_page(sm.output.html, config, frame, figures, target, summary)
