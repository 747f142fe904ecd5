"""Snakemake script: one figure, drawn by its family's module, as PNG and PDF."""
import _path  # noqa: F401
from analysis.figures import common, render

sm = snakemake  # noqa: F821 (provided by Snakemake)
common.save(render.draw(sm.config, sm.wildcards.fig, sm.config["output_dir"], _path.ROOT), sm.output.png, sm.output.pdf)
