"""Modulus family: the apparent modulus at small strain (the slope of stress against strain over
strains 0.01-0.05, analysis/aggregate.py) against the moisture ratio X/X0, one line per value of the
line axes, a panel per modulus (`y`: over the nominal strain, over the interior cells' strain) and
value of `panels`. Reference curves of fresh tissue (`references`) are fitted the same way and marked
at X/X0 = 1 (tissue figure 8)."""
import numpy as np
import pandas as pd

from analysis.aggregate import MODULUS_WINDOW, apparent_modulus
from analysis.figures.common import (figure_title, legend_below, line_colours, line_label, ordered, panel_letter,
                                     row_with_legend, value_label)
from analysis.quantities import MODULI as TITLES
from analysis.references import load as load_reference


def reference_modulus_MPa(config, name, root="."):
    """A reference curve's modulus, fitted over the same strains as the runs'."""
    strain, stress_kPa = load_reference(config["references"][name], root)
    curve = pd.DataFrame({"strain": strain, "stress": stress_kPa * 1e3})
    return apparent_modulus(curve, "strain", "stress") / 1e6


def draw(config, fig, summary, root="."):
    """summary: the per-case summary table restricted to this figure's cases."""
    spec = config["figures"][fig]
    line_axes = spec["lines"] if isinstance(spec["lines"], list) else [spec["lines"]]
    panel_axis = spec.get("panels")
    panel_values = ordered(summary[panel_axis], spec.get("panel_order")) if panel_axis else [None]
    panels = [(y, pv) for pv in panel_values for y in spec["y"]]
    # In the order (and so the colours) of the curves family's lines (analysis/figures/curves.py).
    groups = sorted(summary.groupby(line_axes), key=lambda g: g[0], reverse=True)
    references = spec.get("references", [])
    figure, axes, legend_axes = row_with_legend(len(panels), len(groups) + len(references), sharey=True)
    colours = line_colours(len(groups))
    markers = ["*", "P", "X"]
    for k, ((y, pv), ax) in enumerate(zip(panels, axes)):
        data = summary if pv is None else summary[np.isclose(summary[panel_axis], pv)]
        for (key, rows), colour in zip(groups, colours):
            key = key if isinstance(key, tuple) else (key,)
            rows = rows.loc[rows.index.intersection(data.index)].sort_values("dryness")
            ax.plot(rows["dryness"], rows[y], "o-", color=colour, lw=1.4, label=line_label(config, spec, line_axes, key))
        for i, name in enumerate(references):
            ax.plot([1.0], [reference_modulus_MPa(config, name, root)], markers[i % len(markers)], color="black",
                    ms=9, label=f"{config['references'][name]['label']}, fitted alike")
        title = f"{panel_letter(k)} {TITLES.get(y, y)}"
        if pv is not None:
            title += "\n" + value_label(config, panel_axis, pv)
        ax.set_title(title, fontsize=9)
        ax.set_xlim(0, 1.05)
        ax.set_yscale("log")
        ax.set_xlabel("moisture ratio X/X0")
        ax.set_ylabel(f"apparent modulus, strains {MODULUS_WINDOW[0]}-{MODULUS_WINDOW[1]} [MPa]")
        ax.grid(alpha=0.3, which="both")
    legend_below(legend_axes, axes)
    figure_title(figure, spec["title"])
    return figure
