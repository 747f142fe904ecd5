"""Snakemake script: the convergence table (CSV) and page (HTML)."""
import pandas as pd

import _path  # the analysis package importable; the rule's files by name
from analysis import convergence

sm = snakemake  # noqa: F821 (provided by Snakemake)
config = sm.config
summary = pd.read_csv(sm.input.summary)
anchors = pd.read_csv(sm.input.anchors)
table = convergence.tables(config, summary)
table.to_csv(sm.output.table, index=False)
figures = _path.by_name(sm.input.figures)  # the rule's, in its order
convergence.write_page(sm.output.html, config, table, figures, convergence.comparisons(config, summary),
                       summary=summary, anchors=anchors)
