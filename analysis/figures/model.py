"""Model family (figure 1): the cell at the start of compression in 3-D, cut away to show the
fluid inside, with the plates; and a mid-plane slice beside it."""
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from analysis.figures.common import figure_title
from analysis.figures.shapes import draw_slice
from analysis.results import pick_snapshot


def draw(config, fig, runs, cases):
    import matplotlib.pyplot as plt
    spec = config["figures"][fig]
    case = next(iter(cases.values()))
    path, dried = runs[case.name]
    snap = pick_snapshot(path, "compression_0", dried)
    wall, fluid, tri = snap["wall"] * 1e6, snap["fluid"] * 1e6, snap["triangles"]
    centre = wall.mean(axis=0)
    wall, fluid = wall - centre, fluid - centre

    figure = plt.figure(figsize=(10, 4.8))
    ax = figure.add_subplot(1, 2, 1, projection="3d")
    cut = wall[tri].mean(axis=1)[:, 1] < 0  # the front half of the wall is cut away
    ax.add_collection3d(Poly3DCollection(wall[tri[cut]], facecolor=(0.3, 0.6, 0.3, 0.35),
                                         edgecolor=(0.1, 0.3, 0.1, 0.4), linewidths=0.2))
    inside = fluid[:, 1] < 0
    ax.scatter(fluid[inside, 0], fluid[inside, 1], fluid[inside, 2], s=2, c="tab:blue", alpha=0.5)
    half = 0.5 * case.case.get("compression", {}).get("plate_length_um", 150)
    for z in (snap["plate_top_z_m"], snap["plate_bottom_z_m"]):
        zz = z * 1e6 - centre[2]
        square = [[(-half, -half, zz), (half, -half, zz), (half, half, zz), (-half, half, zz)]]
        ax.add_collection3d(Poly3DCollection(square, facecolor=(0.2, 0.2, 0.2, 0.15), edgecolor="black"))
    lim = half * 1.05
    ax.set_xlim(-lim, lim), ax.set_ylim(-lim, lim), ax.set_zlim(-lim, lim)
    ax.set_xlabel("x [um]"), ax.set_ylabel("y [um]"), ax.set_zlabel("z [um]")
    ax.tick_params(labelsize=7)  # the z label sits beside its tick labels, clear of them
    ax.set_title(f"(a) {len(snap['wall'])} wall particles ({len(tri)} triangles), {len(snap['fluid'])} fluid "
                 "particles; front half cut away", fontsize=8)
    ax2 = figure.add_subplot(1, 2, 2)
    reach = draw_slice(ax2, snap, 2 * half * 1e-6)
    ax2.set_xlim(-reach, reach), ax2.set_ylim(-reach, reach)
    ax2.set_title("(b) mid-plane slice at the start of compression", fontsize=8)
    ax2.set_xlabel("x [um]"), ax2.set_ylabel("z [um]")
    figure.subplots_adjust(wspace=0.3)
    figure_title(figure, spec["title"] + f" ({case.name})", fontsize=10)
    return figure
