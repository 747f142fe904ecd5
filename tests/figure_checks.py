"""What a figure the workflow wrote must show, checked from its content rather than its file size:
the PNG and PDF are byte for byte the figure that the workflow's own drawing code (analysis/figures/
render.py) makes from the results, and that figure has the panels the config asks for, axes titled
with the quantities drawn, and every curve taken from the data of one of the figure's cases."""
import numpy as np
from matplotlib.collections import LineCollection, PathCollection
from matplotlib.colors import to_rgba
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from analysis import aggregate, ensembles, matrix, quantities
from analysis.figures import common, render
from analysis.figures.common import ordered
from analysis.figures.curves import is_strain, is_stress


def coloured(line, colour):
    return to_rgba(line.get_color()) == to_rgba(colour)


def is_reference(line):
    """Reference curves (and plates) are black; simulated curves are coloured."""
    return coloured(line, "black")


def check_figures(config, out, root, tmp_path, figures):
    """Each of `figures` under out/figures/ shows what its spec asks for, drawn from out/runs/."""
    assert figures, "no figure to check"
    for fig in figures:
        figure = render.draw(config, fig, render.files_under(config, fig, out), root)
        CHECKS[config["figures"][fig]["family"]](config, fig, figure, out)
        png, pdf = tmp_path / f"{fig}.png", tmp_path / f"{fig}.pdf"
        common.save(figure, png, pdf)
        for drawn, written in ((png, out / "figures" / f"{fig}.png"), (pdf, out / "figures" / f"{fig}.pdf")):
            assert drawn.read_bytes() == written.read_bytes(), f"{written} is not the figure of its results"


def data_panels(figure):
    """The panels that show data (not the legend's row, not an empty slot)."""
    return [ax for ax in figure.axes if ax.axison and (ax.lines or ax.collections)]


def visible(ax, x, y):
    """Some finite point of (x, y) lies inside the panel's view."""
    (x0, x1), (y0, y1) = sorted(ax.get_xlim()), sorted(ax.get_ylim())
    inside = np.isfinite(x) & np.isfinite(y) & (x >= x0) & (x <= x1) & (y >= y0) & (y <= y1)
    return inside.any()


def check_curves(config, fig, figure, out):
    spec = config["figures"][fig]
    cases, runs = render.inputs(config, fig, render.files_under(config, fig, out))
    series, _ = aggregate.tables([(cases[n], runs[n][0]) for n in cases])
    stage = spec.get("stage", "compression")
    if stage != "all":
        series = series[series["stage"] == (1 if stage == "compression" else 0)]
    x, ys = spec["x"], spec["y"]
    panel_axis = spec.get("panels")
    panel_values = ordered(series[panel_axis], spec.get("panel_order")) if panel_axis else [None]
    panels = data_panels(figure)
    assert len(panels) == len(panel_values) * len(ys), f"{fig}: {len(panels)} panels"
    for k, ax in enumerate(panels):
        y, value = ys[k % len(ys)], panel_values[k // len(ys)]
        assert ax.get_xlabel() == quantities.label(x) and ax.get_ylabel() == quantities.label(y), fig
        in_panel = series if value is None else series[np.isclose(series[panel_axis], value)]
        expected = {name: (c.sort_values("time_s")[x].to_numpy() * quantities.scale(x),
                           c.sort_values("time_s")[y].to_numpy() * quantities.scale(y))
                    for name, c in in_panel.groupby("case")}
        if spec.get("band"):  # one mean line per ensemble: the members' mean on their shared range
            expected = {}
            for key, group in in_panel.groupby(spec["lines"]):
                members = [(m.sort_values("time_s")[x].to_numpy(), m.sort_values("time_s")[y].to_numpy())
                           for _, m in group.groupby(spec["band"])]
                grid, mean, _, _ = ensembles.band(members)
                expected[key] = (grid * quantities.scale(x), mean * quantities.scale(y))
            bands = [c for c in ax.collections if c.get_label().endswith(f"percentile of {len(members)}")]
            assert len(bands) == len(expected), f"{fig} panel {k}: {len(bands)} bands for {len(expected)} ensembles"
        simulated = [line for line in ax.lines if not (is_reference(line) or coloured(line, "grey"))]
        assert len(simulated) == len(expected), f"{fig} panel {k}: {len(simulated)} curves for {len(expected)} cases"
        unmatched = dict(expected)
        for line in simulated:
            lx, ly = (np.asarray(a, dtype=float) for a in line.get_data())
            match = next((n for n, (ex, ey) in unmatched.items()
                          if len(ex) == len(lx) and np.array_equal(ex, lx, equal_nan=True)
                          and np.array_equal(ey, ly, equal_nan=True)), None)
            assert match, f"{fig} panel {k}: a curve ({line.get_label()}) is no case's {y} against {x}"
            del unmatched[match]
            assert visible(ax, lx, ly), f"{fig} panel {k}: the curve of {match} lies outside the axes"
        references = [line for line in ax.lines if is_reference(line)]
        wanted = spec.get("references", []) if is_strain(x) and is_stress(y) else []
        assert [line.get_label() for line in references] == [config["references"][r]["label"] for r in wanted], \
            f"{fig} panel {k}: reference curves {[line.get_label() for line in references]}"
        for line in references:
            assert visible(ax, *(np.asarray(a, dtype=float) for a in line.get_data())), \
                f"{fig} panel {k}: the reference {line.get_label()} is not drawn"


def check_shapes(config, fig, figure, out):
    """One slice per (row, column) that has a case: the wall cut as segments, fluid dots where the fluid is
    particles (a closed cell's is one pressure, drawn as none: the title then names no fluid), titled."""
    spec = config["figures"][fig]
    cases, _ = render.inputs(config, fig, render.files_under(config, fig, out))
    particles = any(matrix.get_key(c.case, "fluid.model") in (None, "sph") for c in cases.values())
    assert ("fluid blue" in " ".join(figure._suptitle.get_text().split())) == particles, f"{fig}: the title's fluid"

    def count(axis):
        if axis == "moment":
            return len(spec.get("moments", ["end"]))
        return len(ordered([c.values[axis] for c in cases.values()])) if axis else 1

    panels = data_panels(figure)
    assert len(panels) == count(spec.get("rows")) * count(spec.get("cols")), f"{fig}: {len(panels)} panels"
    for k, ax in enumerate(panels):
        walls = [c for c in ax.collections if isinstance(c, LineCollection)]
        assert walls and sum(len(c.get_segments()) for c in walls) >= 10, f"{fig} panel {k}: no wall section"
        dots = [c for c in ax.collections if isinstance(c, PathCollection)]
        if particles:
            assert dots and len(dots[0].get_offsets()) > 0, f"{fig} panel {k}: no fluid particles"
        else:
            assert not dots or not len(dots[0].get_offsets()), f"{fig} panel {k}: dots of a closed cell's fluid"
        assert "t = " in ax.get_title(), f"{fig} panel {k}: untitled"
        segments = np.concatenate([np.concatenate(c.get_segments()) for c in walls])
        (x0, x1), (z0, z1) = ax.get_xlim(), ax.get_ylim()
        assert (segments[:, 0] >= x0).all() and (segments[:, 0] <= x1).all() and (segments[:, 1] >= z0).all() \
            and (segments[:, 1] <= z1).all(), f"{fig} panel {k}: the wall runs out of the panel"
    # One scale for all: a shape compares with its neighbour's only at the same scale.
    scales = {(ax.get_xlim(), ax.get_ylim()) for ax in panels}
    assert len(scales) == 1, f"{fig}: panels at {len(scales)} different scales: {sorted(scales)}"


def check_model(config, fig, figure, out):
    """The cell in 3-D (wall triangles, fluid, two plates) beside its mid-plane slice."""
    figure.canvas.draw()  # projects the 3-D polygons onto the picture
    cell, slice_ = figure.axes
    polygons = [c for c in cell.collections if isinstance(c, Poly3DCollection)]
    assert len(polygons) == 3, f"{fig}: the wall and two plates, got {len(polygons)} polygon sets"
    assert len(polygons[0].get_paths()) > 100, f"{fig}: the cut wall has too few triangles"
    assert any(isinstance(c, PathCollection) for c in cell.collections), f"{fig}: no fluid"
    assert any(isinstance(c, LineCollection) for c in slice_.collections), f"{fig}: no slice of the wall"
    assert any(isinstance(c, PathCollection) and len(c.get_offsets()) for c in slice_.collections), \
        f"{fig}: no fluid in the slice"


def check_shrinkage(config, fig, figure, out):
    """V/V0 against X/X0: a line per value of its axis (a tissue's hull and its cells' own volumes
    apart), each point a case's end-of-drying volume at that case's dryness."""
    spec = config["figures"][fig]
    cases, runs = render.inputs(config, fig, render.files_under(config, fig, out))
    _, summary = aggregate.tables([(cases[n], runs[n][0]) for n in cases])
    (ax,) = data_panels(figure)
    tissues = summary.groupby(spec["lines"])["dried_tissue_V_over_V0"].apply(lambda v: v.notna().any())
    drawn = [line for line in ax.lines if not is_reference(line)]
    assert len(drawn) == len(tissues) + tissues.sum(), f"{fig}: {len(drawn)} lines"
    volumes = set(np.round(summary[["dried_V_over_V0", "dried_tissue_V_over_V0"]].stack(), 12))
    for line in drawn:
        x, y = (np.asarray(a, dtype=float) for a in line.get_data())
        assert set(np.round(x, 12)) <= set(np.round(summary["dryness"], 12)), f"{fig}: {x}"
        assert set(np.round(y, 12)) <= volumes, f"{fig}: a line is no case's V/V0"
    references = [line for line in ax.lines if is_reference(line)]
    assert len(references) == len(spec.get("shrinkage_references", [])), fig


def check_modulus(config, fig, figure, out):
    """Moduli against X/X0: a panel per modulus and panel value, a line per group of the line axes,
    every point a case's modulus at its dryness; the references fitted alike, marked at X/X0 = 1."""
    spec = config["figures"][fig]
    cases, runs = render.inputs(config, fig, render.files_under(config, fig, out))
    _, summary = aggregate.tables([(cases[n], runs[n][0]) for n in cases])
    panels = data_panels(figure)
    n_panel_values = summary[spec["panels"]].nunique() if spec.get("panels") else 1
    assert len(panels) == n_panel_values * len(spec["y"]), f"{fig}: {len(panels)} panels"
    moduli = set(np.round(summary[spec["y"]].stack().dropna(), 9))
    for ax in panels:
        drawn = [line for line in ax.lines if not is_reference(line)]
        assert drawn and any(np.isfinite(np.asarray(line.get_ydata(), dtype=float)).any() for line in drawn), fig
        for line in drawn:
            x, y = (np.asarray(a, dtype=float) for a in line.get_data())
            assert set(np.round(x, 12)) <= set(np.round(summary["dryness"], 12)), f"{fig}: {x}"
            assert set(np.round(y[np.isfinite(y)], 9)) <= moduli, f"{fig}: a point is no case's modulus"
        references = [line for line in ax.lines if is_reference(line)]
        assert len(references) == len(spec.get("references", [])), fig
        assert all(list(line.get_xdata()) == [1.0] for line in references), fig


CHECKS = {"curves": check_curves, "shapes": check_shapes, "model": check_model, "shrinkage": check_shrinkage,
          "modulus": check_modulus}
