"""One figure of the config drawn from a results folder, as the workflow draws it: the `figure` rule
(workflow/scripts/figure.py) and the tests that check a figure's content call this one function."""
from analysis import aggregate, comparison, matrix
from analysis.figures import curves, model, modulus, shapes, shrinkage


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
    if family in ("curves", "shrinkage", "modulus"):
        series, summary = aggregate.tables([(cases[n], runs[n][0]) for n in cases])
        if family in ("shrinkage", "modulus"):
            return (shrinkage if family == "shrinkage" else modulus).draw(config, fig, summary, root)
        return curves.draw(config, fig, series, root, overlay=other_run_series(config, fig, cases))
    return (model.draw if family == "model" else shapes.draw)(config, fig, runs, cases)


def other_run_series(config, fig, cases):
    """(series, its label, this run's label) of the other run's results of these cases, for a figure
    that overlays them (analysis/comparison.py); None if it does not or that run has none of them."""
    if not comparison.overlaid(config, fig):
        return None
    found = comparison.other_runs(config, cases)
    if not found:
        return None
    _, other_label, this_label = comparison.other(config)
    series, _ = aggregate.tables([(cases[n], path) for n, path in found.items()])
    return series, other_label, this_label
