"""Snakemake script: the analytic anchors' table of the convergence target (analysis/anchors.py)."""
import _path  # noqa: F401
from analysis import anchors, convergence, matrix

sm = snakemake  # noqa: F821 (provided by Snakemake)
listed = convergence.anchor_runs(sm.config, matrix.expand(sm.config))  # the rule's inputs, in this order
runs = [(kind, case, level, path) for (kind, case, level), path in zip(listed, sm.input.runs)]
anchors.anchor_table(runs).to_csv(sm.output.table, index=False)
