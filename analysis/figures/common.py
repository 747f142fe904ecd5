"""Shared figure helpers: axis titles, value labels, ordering, the figure's title, saving."""
import math
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from analysis.matrix import fmt  # noqa: E402


def axis_title(config, axis):
    if axis == "moment":
        return "moment"
    return config["axes"][axis].get("title", axis)


def value_label(config, axis, value):
    """'X/X0 = 0.5' for an axis value; moments get words."""
    if axis == "moment":
        return moment_label(value)
    return f"{axis_title(config, axis).split(' [')[0]} = {fmt(value)}" + unit_suffix(config, axis)


def line_label(config, spec, axes, key):
    """A line's label: the figure's own words (`line_labels`, keyed by the line's values joined by
    ', ', e.g. "16, unconfined"), else each line axis's value label."""
    own = spec.get("line_labels", {}).get(", ".join(fmt(v) for v in key))
    return own or ", ".join(value_label(config, a, v) for a, v in zip(axes, key))


def unit_suffix(config, axis):
    title = axis_title(config, axis)
    return " " + title[title.index("[") + 1:title.index("]")] if "[" in title else ""


def moment_label(moment):
    if moment == "end_of_drying":
        return "end of drying"
    if moment == "end":
        return "end of compression"
    if moment.startswith("strain_"):
        return f"strain {moment.split('_')[1]}"
    return f"compression {int(moment.split('_')[1]) * 25}%"


def ordered(values, order=None):
    """Distinct values, in the configured order if given, else descending (fresh first)."""
    distinct = sorted(set(values), reverse=True)
    if order:
        return [v for v in order if any(abs(v - d) < 1e-12 for d in distinct)]
    return distinct


def grid(n_rows, n_cols, panel_w=3.2, panel_h=3.0, **kw):
    fig, axes = plt.subplots(n_rows, n_cols, figsize=(panel_w * n_cols + 0.6, panel_h * n_rows + 0.8),
                             squeeze=False, layout="constrained", **kw)
    return fig, axes


# A legend column of the row below the panels takes about this width (labels of ~45 characters at 7 pt).
LEGEND_COLUMN_IN = 2.9


def legend_columns(width_in, n_entries):
    return max(1, min(n_entries, int(width_in // LEGEND_COLUMN_IN)))


def row_with_legend(n_cols, n_entries, panel_w=3.2, panel_h=3.0, sharey=False):
    """One row of panels of a fixed size and, below them, a row for the legend. A long legend then
    takes height below the panels, never width from them (beside a single panel it squeezed the
    panel to a sliver). Returns the figure, the panels and the legend's axes."""
    width = panel_w * n_cols + 0.6
    legend_h = 0.2 + 0.19 * math.ceil(max(n_entries, 1) / legend_columns(width, n_entries))
    figure = plt.figure(figsize=(width, panel_h + 0.8 + legend_h), layout="constrained")
    cells = figure.add_gridspec(2, n_cols, height_ratios=[panel_h, legend_h])
    panels = []
    for j in range(n_cols):
        panels.append(figure.add_subplot(cells[0, j], sharey=panels[0] if sharey and panels else None))
    legend_axes = figure.add_subplot(cells[1, :])
    legend_axes.set_axis_off()
    return figure, panels, legend_axes


def grid_with_legend(n_rows, n_cols, n_entries, panel_w=3.2, panel_h=3.0):
    """row_with_legend for a grid of panels: n_rows x n_cols panels of one size, the legend's row below them.
    Returns the figure, the panels (n_rows x n_cols, a list of lists) and the legend's axes."""
    width = panel_w * n_cols + 0.6
    legend_h = 0.2 + 0.19 * math.ceil(max(n_entries, 1) / legend_columns(width, n_entries))
    figure = plt.figure(figsize=(width, panel_h * n_rows + 0.8 + legend_h), layout="constrained")
    cells = figure.add_gridspec(n_rows + 1, n_cols, height_ratios=[panel_h] * n_rows + [legend_h])
    panels = [[figure.add_subplot(cells[i, j]) for j in range(n_cols)] for i in range(n_rows)]
    legend_axes = figure.add_subplot(cells[n_rows, :])
    legend_axes.set_axis_off()
    return figure, panels, legend_axes


def legend_below(legend_axes, panels):
    """Every distinct label of the panels, once, in the legend row (row_with_legend)."""
    handles, labels = {}, []
    for ax in panels:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            if label not in handles:
                handles[label] = handle
                labels.append(label)
    if labels:
        columns = legend_columns(legend_axes.figure.get_figwidth(), len(labels))
        legend_axes.legend([handles[label] for label in labels], labels, loc="upper center", fontsize=7,
                           ncol=columns, frameon=False, borderaxespad=0.0)


def line_colours(n):
    """n colours of one sequential map, for lines ordered by an axis's value."""
    cmap = plt.get_cmap("viridis")
    return [cmap(0.9 * i / max(1, n - 1)) for i in range(n)]


def panel_letter(index):
    return "(" + "abcdefghijklmnopqrstuvwxyz"[index] + ")"


# The title may take this share of the figure's width: the saved picture (bbox_inches="tight") grows to
# hold whatever is drawn, so a title wider than the panels widened it beside them.
TITLE_WIDTH_SHARE = 0.96


def figure_title(figure, text, fontsize=11):
    """The figure's title, broken into as many lines as it needs to fit the figure's width; with the
    constrained layout the panels move down to make room for the extra lines."""
    title = figure.suptitle(text, fontsize=fontsize)
    renderer = figure.canvas.get_renderer()
    room = TITLE_WIDTH_SHARE * figure.get_figwidth() * figure.dpi
    columns = len(text)
    while columns > 20 and title.get_window_extent(renderer).width > room:
        columns = int(columns * min(0.95, room / title.get_window_extent(renderer).width))
        title.set_text(textwrap.fill(text, columns, break_on_hyphens=False))
    return title


def save(figure, png, pdf):
    """PNG and PDF; without a creation date, so that the same data give the same bytes."""
    figure.savefig(png, dpi=130, bbox_inches="tight")
    figure.savefig(pdf, bbox_inches="tight", metadata={"CreationDate": None})
    plt.close(figure)
