"""Shapes family: mid-plane slices (y = cell centre) of particle snapshots; the wall is the
intersection of its triangles with the plane, the fluid particles near the plane are dots, and the
plates are drawn where they are (figures 2, 3, 8, 17). In a tissue the plane goes through the row of
cells nearest the tissue's centre, and each cell's wall has its own colour."""
import numpy as np
from matplotlib.collections import LineCollection

from analysis.figures.common import figure_title, grid, moment_label, ordered, panel_letter, value_label
from analysis.results import pick_snapshot

ROW_TIE_M = 20e-6  # rows this much nearer the middle than another count as equally near (rows are ~100 um apart)

# A tissue's walls: neighbouring cells in the slice get different colours (none of them fluid blue).
TISSUE_COLOURS = ["darkgreen", "tab:orange", "tab:purple", "tab:brown", "tab:olive", "tab:red", "tab:pink",
                  "tab:gray", "tab:cyan"]


def wall_section(wall, triangles, y0):
    """Segments where the plane y = y0 cuts the wall triangles (x, z pairs)."""
    d = wall[:, 1] - y0
    segments = []
    for tri in triangles:
        points = []
        for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
            if (d[a] < 0) != (d[b] < 0):
                t = d[a] / (d[a] - d[b])
                p = wall[a] + t * (wall[b] - wall[a])
                points.append((p[0], p[2]))
        if len(points) == 2:
            segments.append(points)
    return np.array(segments)


def slice_plane_y(wall, wall_cell):
    """y of the plane: the centre of the cell whose centre lies nearest the middle in y (for one
    cell, its centre). Of rows about as near (within ROW_TIE_M: an even count of rows), the first cell's,
    so that every panel of a figure cuts the same row."""
    centres = np.array([wall[wall_cell == c, 1].mean() for c in np.unique(wall_cell)])
    distance = np.abs(centres - wall[:, 1].mean())
    return centres[np.nonzero(distance <= distance.min() + ROW_TIE_M)[0][0]]


def draw_slice(ax, snap, plate_length_m, scale=1e6):
    """The mid-plane slice of one snapshot; returns the half-width [um] of the square that holds it."""
    wall, fluid, wall_cell = snap["wall"], snap["fluid"], snap["wall_cell"]
    centre = wall.mean(axis=0)
    centre[1] = slice_plane_y(wall, wall_cell)
    cells = np.unique(wall_cell)
    for c in cells:
        in_cell = np.all(wall_cell[snap["triangles"]] == c, axis=1)
        segments = wall_section(wall, snap["triangles"][in_cell], centre[1])
        if len(segments):
            colour = "darkgreen" if len(cells) == 1 else TISSUE_COLOURS[c % len(TISSUE_COLOURS)]
            ax.add_collection(LineCollection((segments - centre[[0, 2]]) * scale, colors=colour, linewidths=1.3))
    spacing = np.median(np.abs(np.diff(np.sort(fluid[:, 1])))[np.abs(np.diff(np.sort(fluid[:, 1]))) > 0]) \
        if len(fluid) > 1 else 1e-6
    near = np.abs(fluid[:, 1] - centre[1]) < max(spacing, 2e-6) * 2
    ax.scatter((fluid[near, 0] - centre[0]) * scale, (fluid[near, 2] - centre[2]) * scale, s=4, c="tab:blue",
               alpha=0.6, linewidths=0)
    period = snap.get("period_x_m", float("nan")) * scale
    reach = np.abs(wall[:, [0, 2]] - centre[[0, 2]]).max() * scale * 1.1
    # A periodic slab's plates cover every period (model.md §10b): drawn across the panel, with the
    # period that repeats marked by dashed lines about the slab's centre.
    half = 0.5 * plate_length_m * scale if not np.isfinite(period) else reach
    for z in (snap["plate_top_z_m"], snap["plate_bottom_z_m"]):
        if np.isfinite(z):
            ax.plot([-half, half], [(z - centre[2]) * scale] * 2, color="black", lw=2.5)
    if np.isfinite(period):
        for x in (-0.5 * period, 0.5 * period):
            ax.axvline(x, color="grey", ls="--", lw=0.8)
    ax.set_aspect("equal")
    ax.tick_params(labelsize=7)
    return max(half, reach)  # the half-width of a square that holds the plates and the whole wall


def draw(config, fig, runs, cases):
    """runs: {case name: (result path, dried path)}; cases: {name: Case} of this figure."""
    spec = config["figures"][fig]
    moments = spec.get("moments", ["end"])
    row_axis, col_axis = spec.get("rows"), spec.get("cols")

    def values(axis, order_key):
        if axis == "moment":
            return moments
        if axis is None:
            return [None]
        return ordered([c.values[axis] for c in cases.values()], spec.get(order_key))

    rows, cols = values(row_axis, "row_order"), values(col_axis, "col_order")
    figure, axes = grid(len(rows), len(cols), panel_w=2.7, panel_h=2.7)
    tissue = periodic = particles = False
    drawn = {}  # axes: the half-width its slice needs
    for i, rv in enumerate(rows):
        for j, cv in enumerate(cols):
            ax = axes[i][j]
            chosen = {row_axis: rv, col_axis: cv}
            moment = chosen.get("moment", moments[0])
            match = [c for c in cases.values()
                     if all(a in (None, "moment") or np.isclose(c.values[a], v) for a, v in chosen.items())]
            if not match:
                ax.set_axis_off()
                continue
            path, dried = runs[match[0].name]
            snap = pick_snapshot(path, moment, dried)
            tissue = tissue or snap["wall_cell"].max() > 0
            periodic = periodic or np.isfinite(snap["period_x_m"])
            particles = particles or len(snap["fluid"]) > 0  # a closed cell's fluid is one pressure: no dots
            plate_length = match[0].case.get("compression", {}).get("plate_length_um", 150) * 1e-6
            drawn[ax] = draw_slice(ax, snap, plate_length)
            label = [value_label(config, a, v) for a, v in ((row_axis, rv), (col_axis, cv)) if a and a != "moment"]
            # Two short lines: long one-line titles ran into the neighbouring panels' titles.
            ax.set_title(f"{panel_letter(i * len(cols) + j)} " + ", ".join(label) +
                         f"\n{moment_label(moment)}, t = {snap['time_s'] * 1e6:.1f} us", fontsize=7)
            if j == 0:
                ax.set_ylabel("z [um]", fontsize=8)
            if i == len(rows) - 1:
                ax.set_xlabel("x [um]", fontsize=8)
    # One scale for every panel (a 200 um cell is wider than the plates; a slab at the end of drying
    # stands taller than compressed), so that shapes and sizes compare across panels.
    reach = max(drawn.values(), default=1.0)
    for ax in drawn:
        ax.set_xlim(-reach, reach)
        ax.set_ylim(-reach, reach)
    walls = "walls coloured by cell" if tissue else "wall green"
    period = ", the period dashed" if periodic else ""
    fluid = ", fluid blue" if particles else ""
    figure_title(figure, spec["title"] + f" (mid-plane slice: {walls}{fluid}, plates black{period})", fontsize=10)
    return figure
