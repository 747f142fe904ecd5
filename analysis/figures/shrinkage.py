"""Shrinkage family: volume at the end of drying, V/V0, against the moisture ratio X/X0, one line per
value of an axis (e.g. cells), beside reference lines (`shrinkage_references`). A single cell's V is its
enclosed volume; a tissue's is the hull of all its walls (solid), with the sum of its cells' own
volumes dashed: the difference is the air the tissue takes in or loses (tissue figure 4)."""
import numpy as np

from analysis.figures.common import figure_title, legend_below, line_colours, ordered, row_with_legend, value_label
from analysis.references import load_shrinkage


def draw(config, fig, summary, root="."):
    """summary: the per-case summary table (analysis/aggregate.py) restricted to this figure's cases."""
    spec = config["figures"][fig]
    line_axis = spec["lines"]
    groups = ordered(summary[line_axis])
    references = spec.get("shrinkage_references", [])
    tissue_groups = [v for v in groups
                     if summary.loc[np.isclose(summary[line_axis], v), "dried_tissue_V_over_V0"].notna().any()]
    figure, (ax,), legend_axes = row_with_legend(1, len(groups) + len(tissue_groups) + len(references),
                                                 panel_w=4.6, panel_h=3.6)
    colours = line_colours(len(groups))
    for value, colour in zip(groups, colours):
        rows = summary[np.isclose(summary[line_axis], value)].sort_values("dryness")
        name = value_label(config, line_axis, value)
        if rows["dried_tissue_V_over_V0"].notna().any():
            ax.plot(rows["dryness"], rows["dried_tissue_V_over_V0"], "o-", color=colour, lw=1.4,
                    label=f"{name}: tissue (hull of its walls)")
            ax.plot(rows["dryness"], rows["dried_V_over_V0"], "s--", color=colour, lw=1.1, ms=4,
                    label=f"{name}: its cells' own volumes")
        else:
            ax.plot(rows["dryness"], rows["dried_V_over_V0"], "o-", color=colour, lw=1.4, label=name)
    styles = [":", "-.", "--"]
    for i, name in enumerate(references):
        ref = config["shrinkage_references"][name]
        x, v = load_shrinkage(ref, root)
        if len(x) == 1:
            ax.plot(x, v, "k*", ms=9, label=ref["label"])
        else:
            ax.plot(x, v, color="black", ls=styles[i % len(styles)], lw=1.1, label=ref["label"])
    ax.set_xlim(0, 1.05)
    ax.set_ylim(0, 1.1)
    ax.set_xlabel("moisture ratio X/X0")
    ax.set_ylabel("volume at the end of drying V/V0")
    ax.grid(alpha=0.3)
    legend_below(legend_axes, [ax])
    figure_title(figure, spec["title"])
    return figure
