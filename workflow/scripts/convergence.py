"""Snakemake script: the convergence table (CSV) and page (HTML)."""
import pandas as pd

import _path  # noqa: F401
from analysis import convergence, matrix

sm = snakemake  # noqa: F821 (provided by Snakemake)
config = sm.config
summary = pd.read_csv(sm.input.summary)
anchors = pd.read_csv(sm.input.anchors)
table = convergence.tables(config, summary)
table.to_csv(sm.output.table, index=False)
figures = {f: f"{config['output_dir']}/figures/{f}.png" for f in matrix.target_figures(config, "convergence")}
convergence.write_page(sm.output.html, config, table, figures, convergence.comparisons(config, summary),
                       summary=summary, anchors=anchors)
