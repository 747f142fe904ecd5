"""Snakemake script: one figure, drawn by its family's module from the files its rule lists, as PNG and PDF."""
import _path
from analysis.figures import common, render

sm = snakemake  # noqa: F821 (provided by Snakemake)
files = {"runs": _path.by_name(sm.input.runs), "dried": _path.by_name(sm.input.dried),
         "column_runs": _path.by_name(sm.input.column_runs)}
common.save(render.draw(sm.config, sm.wildcards.fig, files, _path.ROOT), sm.output.png, sm.output.pdf)
