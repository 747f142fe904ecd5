"""Curves family: one quantity against time or strain, lines by an axis, panels by an axis or by
quantity, with experimental reference curves on stress-strain panels (figures 4-7, 9-16, 18). With
`band: <axis>` each line is an ensemble over that axis's values (seeds): its mean and its 10th-90th
percentile band (analysis/ensembles.py). With `overlay` (analysis/figures/render.py: a run beside this
one, analysis/comparison.py, and this run's further claim columns, analysis/columns.py) each line has their
curves of the same case beside it in the same colour, each source in its own line style, and this run's
band beyond strain 0.05 shaded where one exists."""
import numpy as np

from analysis import quantities
from analysis.ensembles import BAND_PERCENTILES, band
from analysis.figures.common import (figure_title, legend_below, line_colours, line_label, ordered, panel_letter,
                                     row_with_legend, value_label)
from analysis.references import load as load_reference


def draw(config, fig, series, root=".", overlay=None):
    """series: the tidy time series table restricted to this figure's cases. overlay: render.overlay's
    {'this', 'lines', 'band', 'band_label'}, or None."""
    spec = config["figures"][fig]
    x, ys = spec["x"], spec["y"]
    stage = spec.get("stage", "compression")
    if stage != "all":
        series = series[series["stage"] == (1 if stage == "compression" else 0)]
        if overlay is not None:
            wanted = 1 if stage == "compression" else 0
            overlay = dict(overlay, lines=[(s[s["stage"] == wanted], label, ls) for s, label, ls in overlay["lines"]])
    line_axes = spec.get("lines") or []
    line_axes = [line_axes] if isinstance(line_axes, str) else line_axes
    panel_axis = spec.get("panels")
    panel_values = ordered(series[panel_axis], spec.get("panel_order")) if panel_axis else [None]
    panels = [(y, pv) for pv in panel_values for y in ys]
    grouper = line_axes[0] if len(line_axes) == 1 else line_axes
    n_lines = series.groupby(grouper).ngroups if line_axes else 1
    n_references = len(spec.get("references", [])) if is_strain(x) and any(map(is_stress, ys)) else 0

    per_line = 2 if spec.get("band") else 1  # a band's line and its shaded band each have an entry
    # the runs' line styles, and the band's entry
    n_styles = (1 + len(overlay["lines"]) + bool(overlay["band"])) if overlay is not None else 0
    figure, axes, legend_axes = row_with_legend(len(panels), per_line * n_lines + n_references + n_styles,
                                                sharey=len(ys) == 1)
    # One colour per line across all panels, so that a panel missing some lines keeps the legend's colours.
    keys = sorted(series.groupby(grouper).groups, reverse=True) if line_axes else [()]
    colour_of = dict(zip(keys, line_colours(len(keys))))
    for k, ((y, pv), ax) in enumerate(zip(panels, axes)):
        data = series if pv is None else series[np.isclose(series[panel_axis], pv)]
        groups = sorted(data.groupby(grouper) if line_axes else [((), data)], key=lambda g: g[0], reverse=True)
        for key, curve in groups:
            colour = colour_of[key]
            key = key if isinstance(key, tuple) else (key,)
            label = line_label(config, spec, line_axes, key)
            if spec.get("band"):
                _draw_band(ax, curve, spec["band"], x, y, colour, label)
                continue
            curve = curve.sort_values("time_s")
            ax.plot(curve[x] * quantities.scale(x), curve[y] * quantities.scale(y), color=colour, lw=1.4,
                    label=label or None)
            if overlay is not None:
                case = curve["case"].iloc[0]
                for other_series, _, ls in overlay["lines"]:
                    _draw_other(ax, other_series, case, x, y, colour, ls)
                if case in overlay["band"] and x == "nominal_strain" and y == "plate_stress_Pa":
                    grid, low, high = overlay["band"][case]
                    ax.fill_between(grid, low, high, color=colour, alpha=0.2, lw=0)
        if overlay is not None:
            ax.plot([], [], color="0.3", lw=1.4, label=f"solid: {overlay['this']}")
            for _, label, ls in overlay["lines"]:
                ax.plot([], [], color="0.3", lw=1.0, ls=ls, label=f"{STYLE_NAMES[ls]}: {label}")
            if overlay["band"]:
                ax.fill_between([], [], [], color="0.3", alpha=0.2, lw=0, label=overlay["band_label"])
        if is_strain(x) and is_stress(y):
            _draw_references(config, spec, ax, root)
        title = panel_letter(k) if len(panels) > 1 else ""
        if pv is not None:
            title += " " + value_label(config, panel_axis, pv)
        ax.set_title(title.strip(), fontsize=10)
        ax.set_xlabel(quantities.label(x))
        ax.set_ylabel(quantities.label(y))
        ax.grid(alpha=0.3)
        if stage == "all" and x == "time_s":
            _mark_compression_start(ax, data)
    legend_below(legend_axes, axes)  # below the panels: it never covers a curve nor narrows a panel
    figure_title(figure, spec["title"])
    return figure


def _draw_band(ax, curve, band_axis, x, y, colour, label):
    """An ensemble's mean line and its percentile band, its members taken from the band axis's values."""
    members = [m.sort_values("time_s") for _, m in curve.groupby(band_axis)]
    grid, mean, low, high = band([(m[x].to_numpy(), m[y].to_numpy()) for m in members])
    if not len(grid):
        return
    sx, sy = quantities.scale(x), quantities.scale(y)
    lo, hi = BAND_PERCENTILES
    ax.fill_between(grid * sx, low * sy, high * sy, color=colour, alpha=0.25, lw=0,
                    label=f"{label}: {lo}th-{hi}th percentile of {len(members)}")
    ax.plot(grid * sx, mean * sy, color=colour, lw=1.6, label=f"{label}: mean of {len(members)}")


STYLE_NAMES = {"--": "dashed", ":": "dotted", "-.": "dash-dotted", "-": "solid, thin"}


def _draw_other(ax, other_series, case, x, y, colour, ls):
    """Another source's curve of the same case, in the same colour and its own line style (nothing if it
    has none)."""
    curve = other_series[other_series["case"] == case].sort_values("time_s")
    if not curve.empty:
        ax.plot(curve[x] * quantities.scale(x), curve[y] * quantities.scale(y), color=colour, lw=1.0, ls=ls)


def is_strain(quantity):
    """A strain of the cells (nominal, the interior's): tissue data's strain shares its axis."""
    return quantity in ("nominal_strain", "cell_strain", "gauge_strain")


def is_stress(quantity):
    """A stress (plate, section, contact, footprint): the reference curves of tissue stress share its axes."""
    return quantity.endswith("_stress_Pa")


def _mark_compression_start(ax, data):
    """A dotted line where each case's compression began (drying ends at its own steady state)."""
    for start in sorted(set(data[data["stage"] == 0].groupby("case")["time_s"].max())):
        ax.axvline(start * 1e6, color="grey", ls=":", lw=1)


def _draw_references(config, spec, ax, root):
    """Reference curves share the axes (strain as a fraction, stress in kPa), cut at the
    simulated strain range so the simulation stays readable."""
    styles = ["--", "-.", ":"]
    x_max = ax.get_xlim()[1]
    for i, name in enumerate(spec.get("references", [])):
        ref = config["references"][name]
        strain, stress_kPa = load_reference(ref, root)
        keep = strain <= max(x_max, 1e-9)
        ax.plot(strain[keep], stress_kPa[keep], color="black", ls=styles[i % len(styles)], lw=1.1,
                label=ref["label"])
