"""Snakemake script: one figure, drawn by its family's module, as PNG and PDF."""
import pathlib

import _path  # noqa: F401
from analysis import aggregate, matrix
from analysis.figures import common, curves, model, shapes, shrinkage

sm = snakemake  # noqa: F821 (provided by Snakemake)
config, fig = sm.config, sm.wildcards.fig
cases = matrix.expand(config)
names = matrix.figure_cases(config, fig, cases)
family = config["figures"][fig]["family"]
root = _path.ROOT
if family in ("curves", "shrinkage"):
    series, summary = aggregate.tables([(cases[n], f"{config['output_dir']}/runs/{n}.h5") for n in names])
    figure = curves.draw(config, fig, series, root) if family == "curves" else shrinkage.draw(config, fig, summary, root)
else:
    runs = {n: (f"{config['output_dir']}/runs/{n}.h5", f"{config['output_dir']}/runs/dried/{cases[n].dried}.h5")
            for n in names}
    draw = model.draw if family == "model" else shapes.draw
    figure = draw(config, fig, runs, {n: cases[n] for n in names})
common.save(figure, sm.output.png, sm.output.pdf)
