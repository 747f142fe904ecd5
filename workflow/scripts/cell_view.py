"""Snakemake script: the 3-D page of one case and its data (analysis/cell_view.py)."""
import _path  # noqa: F401
from analysis import cell_view

sm = snakemake  # noqa: F821 (provided by Snakemake)
cell_view.write(sm.wildcards.case, sm.input.run, sm.input.dried, sm.output.html, sm.output.data, sm.params.plate_um)
