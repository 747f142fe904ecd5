"""One figure of the config drawn from a results folder, as the workflow draws it: the `figure` rule
(workflow/scripts/figure.py) and the tests that check a figure's content call this one function."""
from analysis import aggregate, matrix
from analysis.figures import curves, model, shapes, shrinkage


def inputs(config, fig, output_dir):
    """(cases of the figure {name: Case}, {name: (result path, dried-state path)}) under output_dir."""
    cases = matrix.expand(config)
    names = matrix.figure_cases(config, fig, cases)
    runs = {n: (f"{output_dir}/runs/{n}.h5", f"{output_dir}/runs/dried/{cases[n].dried}.h5") for n in names}
    return {n: cases[n] for n in names}, runs


def draw(config, fig, output_dir, root="."):
    """The matplotlib Figure of `fig` (a key of config['figures']) from the runs under output_dir."""
    family = config["figures"][fig]["family"]
    cases, runs = inputs(config, fig, output_dir)
    if family in ("curves", "shrinkage"):
        series, summary = aggregate.tables([(cases[n], runs[n][0]) for n in cases])
        return curves.draw(config, fig, series, root) if family == "curves" else shrinkage.draw(config, fig, summary, root)
    return (model.draw if family == "model" else shapes.draw)(config, fig, runs, cases)
