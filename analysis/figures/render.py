"""One figure of the config drawn from its files, as the workflow draws it: the `figure` rule
(workflow/scripts/figure.py) passes the files its inputs list, and the tests that check a figure's content
pass those of a results folder (files_under); both call this one function.

A figure's files: {"runs": {case: result}, "dried": {dried state's name: its file}, "column_runs": {case:
result}}, the last the claim columns' counterparts and band drawn beside it."""
import os

from analysis import aggregate, columns, comparison, matrix
from analysis.figures import curves, model, modulus, shapes, shrinkage


def files_under(config, fig, output_dir, cases=None):
    """The files of `fig` in a results folder, as its `figure` rule lists them (workflow/rules/analysis.smk);
    cases: matrix.expand(config), if the caller has it."""
    cases = cases or matrix.expand(config)
    names = matrix.figure_cases(config, fig, cases)
    beside = columns.overlay_cases(config, fig, cases, {n: cases[n] for n in names})
    return {"runs": {n: f"{output_dir}/runs/{n}.h5" for n in names},
            "dried": {cases[n].dried: f"{output_dir}/runs/dried/{cases[n].dried}.h5" for n in names},
            "column_runs": {n: f"{output_dir}/runs/{n}.h5" for n in beside}}


def inputs(config, fig, files):
    """(cases of the figure {name: Case}, {name: (result path, dried-state path)}) from its files."""
    cases = matrix.expand(config)
    names = matrix.figure_cases(config, fig, cases)
    runs = {n: (files["runs"][n], files["dried"][cases[n].dried]) for n in names}
    return {n: cases[n] for n in names}, runs


def draw(config, fig, files, root="."):
    """The matplotlib Figure of `fig` (a key of config['figures']) from its files (above)."""
    family = config["figures"][fig]["family"]
    cases, runs = inputs(config, fig, files)
    if family in ("curves", "shrinkage", "modulus"):
        series, summary = aggregate.tables([(cases[n], runs[n][0]) for n in cases])
        if family in ("shrinkage", "modulus"):
            return (shrinkage if family == "shrinkage" else modulus).draw(config, fig, summary, root)
        return curves.draw(config, fig, series, root, overlay=overlay(config, fig, cases, {**files["column_runs"], **files["runs"]}))
    return (model.draw if family == "model" else shapes.draw)(config, fig, runs, cases)


def overlay(config, fig, cases, column_runs):
    """column_runs: {case: result} of this run's cases the overlay may read (the figure's own among them).
    What a figure named in compare_with.figures draws beside this run's curves (analysis/comparison.py,
    analysis/columns.py), or None: {'this': this run's label, 'lines': [(series under this figure's case
    names, label, line style)], 'band': {case: (strain, low kPa, high kPa)}, 'band_label': str}. The lines
    are the other run's (dashed; its label says where it was made by other code) and each further claim
    column's counterpart of every case."""
    if not comparison.overlaid(config, fig):
        return None
    every = columns.default_cases(config, matrix.expand(config))
    _, other_label, this_label = comparison.other(config)
    lines = []
    found = comparison.other_runs(config, cases)
    if found:
        made, differs = comparison.other_made_by(config)
        if differs:
            other_label += f" (made by commit {made['commit']})" if made else " (made by unknown code)"
        lines.append((aggregate.tables([(cases[n], path) for n, path in found.items()])[0], other_label, "--"))
    column_specs = list(columns.specs(config).values())
    for spec in column_specs[1:]:
        pairs = {n: columns.counterpart_name(config, every, cases[n], spec["where"]) for n in cases}
        runs = [(every[o], column_runs[o], n) for n, o in pairs.items() if o in column_runs]
        runs = [r for r in runs if os.path.exists(r[1])]
        if runs:
            series, _ = aggregate.tables([(case, path) for case, path, _ in runs])
            series["case"] = series["case"].map({case.name: n for case, _, n in runs})
            lines.append((series, spec["label"], spec.get("line_style", ":")))
    band, band_label = {}, ""
    if column_specs and column_specs[0].get("band"):
        band, band_label = band_of(config, every, cases, column_specs[0], column_runs)
    return {"this": this_label, "lines": lines, "band": band, "band_label": band_label}


def band_of(config, every, cases, spec, column_runs):
    """column_runs: as overlay's. ({case: (strain, low, high)}, label) of the first claim column's band beyond strain 0.05, for the
    figure's cases, from the column's cases of every dryness at the paper's base and their changes."""
    base = {axis: matrix.base_value(config, axis) for axis in config["axes"]}
    values = columns.values_of(config, base, spec["where"])
    runs = [(every[n], column_runs[n]) for n in sorted(columns.band_cases(config, every, cases, spec)) if n in column_runs]
    runs = [r for r in runs if os.path.exists(r[1])]
    if not runs:
        return {}, ""
    series, summary = aggregate.tables(runs)
    axes = list(config["axes"])
    band = columns.band_envelopes(config, summary, series, values, spec["band"], axes,
                                  [n for n in cases if n in set(summary["case"])])
    label = (f"shaded: its band beyond strain {columns.BAND_FROM} ("
             + "; ".join(c["label"] for c in spec["band"].values()) + ")")
    return {n: b for n, b in band.items() if len(b[0])}, label
