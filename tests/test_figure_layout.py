"""Every figure of the default and CI configs is readable whatever its legend: each data panel keeps at
least MIN_PANEL_IN in the saved figure, no legend covers more than MAX_LEGEND_SHARE of a panel, and
the saved picture is no wider than the figure (a title or legend wider than the panels widened it).
Curves are drawn from synthetic series (one per case of the figure), shrinkage and moduli from a
synthetic summary, shapes and the model figure from one small real run, shared by every case."""
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from analysis import matrix, quantities
from analysis.figures import curves, model, modulus, shapes, shrinkage
from conftest import CI, workflow_config
from figure_checks import data_panels

MIN_PANEL_IN = (2.2, 2.0)  # width, height
MAX_LEGEND_SHARE = 0.05
MAX_WIDENING_IN = 0.02  # the saved picture beyond the figure's own width, either side


def configs(root):
    return {"default": workflow_config(root, []), "ci": workflow_config(root, CI)}


def synthetic_series(case, k):
    """A drying record, then a compression: every drawable quantity a smooth curve, case k a bit apart."""
    n = 40
    t = np.arange(n + 1) * 1e-6
    strain = np.concatenate([[np.nan], np.linspace(0, 0.2, n)])
    rows = {name: (1 + 0.1 * k) * (1 + np.linspace(0, 1, n + 1)) / scale
            for name, (_, scale) in quantities.DRAWABLE.items()}
    rows.update(stage=np.r_[0.0, np.ones(n)], time_s=t, compression_time_s=np.r_[np.nan, t[:-1]],
                nominal_strain=strain, plate_stress_Pa=(1 + 0.1 * k) * 5e5 * strain)
    return pd.DataFrame(rows).assign(case=case.name, **case.values)


def synthetic_summary(cases):
    """A summary row per case: its axes' values, and a volume and moduli that vary across the cases."""
    rows = [dict(case.values, case=case.name, dried_V_over_V0=0.3 + 0.7 * case.values.get("dryness", 1.0),
                 dried_tissue_V_over_V0=0.35 + 0.7 * case.values.get("dryness", 1.0),
                 modulus_MPa_nominal=0.2 + 0.1 * k, modulus_MPa_gauge=0.3 + 0.1 * k)
            for k, case in enumerate(cases)]
    return pd.DataFrame(rows)


def draw(config, fig, root, small_run):
    """small_run: (result, dried state) that every case of a shapes or model figure is drawn from."""
    cases = matrix.expand(config)
    names = matrix.figure_cases(config, fig, cases)
    family = config["figures"][fig]["family"]
    if family == "curves":
        series = pd.concat([synthetic_series(cases[n], k) for k, n in enumerate(names)], ignore_index=True)
        return curves.draw(config, fig, series, root)
    if family in ("shrinkage", "modulus"):
        summary = synthetic_summary([cases[n] for n in names])
        return (shrinkage if family == "shrinkage" else modulus).draw(config, fig, summary, root)
    runs = {n: small_run for n in names}
    return (model.draw if family == "model" else shapes.draw)(config, fig, runs, {n: cases[n] for n in names})


def figure_layouts(config):
    """What a figure's layout depends on: per figure, its spec and its cases' count."""
    cases = matrix.expand(config)
    return {fig: (spec, len(matrix.figure_cases(config, fig, cases))) for fig, spec in config["figures"].items()}


def test_the_ci_configs_figures_are_laid_out_as_the_defaults(root):
    """config/ci.yaml makes the cells smaller, not the figures: each figure has the default's spec and as
    many cases, so the layout check of the default's figures below holds for the CI's (drawing them again
    took 90 s of the test command). A figure that comes to differ fails here: then check both."""
    layouts = {which: figure_layouts(config) for which, config in configs(root).items()}
    assert len(layouts["default"]) >= 18
    assert layouts["ci"] == layouts["default"]


def test_every_figure_keeps_its_panels_readable(root, small_runs, tmp_path):
    small_run = small_runs[1.0]
    which = "default"
    config = configs(root)[which]
    checked = 0
    for fig in sorted(config["figures"]):
        figure = draw(config, fig, root, small_run)
        figure.savefig(tmp_path / f"{fig}.png", dpi=130, bbox_inches="tight")
        figure.canvas.draw()
        saved = figure.get_tightbbox(figure.canvas.get_renderer())  # inches, as bbox_inches="tight" saves
        assert saved.x0 >= -MAX_WIDENING_IN and saved.x1 <= figure.get_figwidth() + MAX_WIDENING_IN, \
            f"{which} {fig} ({config['figures'][fig]['family']}): the saved picture spans x = {saved.x0:.2f} to " \
            f"{saved.x1:.2f} in, beyond the figure's 0 to {figure.get_figwidth():.2f} in: " \
            f"{[t.get_text()[:40] for t in widening_texts(figure)]}"
        panels = data_panels(figure)
        assert panels, f"{which} {fig}: no data panel"
        legends = [ax.get_legend() for ax in figure.axes if ax.get_legend()] + list(figure.legends)
        for ax in panels:
            box = ax.get_window_extent()
            width, height = box.width / figure.dpi, box.height / figure.dpi
            assert width >= MIN_PANEL_IN[0] and height >= MIN_PANEL_IN[1], \
                f"{which} {fig}: a panel is {width:.2f} x {height:.2f} in, less than {MIN_PANEL_IN}"
            for legend in legends:
                overlap = box.intersection(box, legend.get_window_extent())
                share = overlap.width * overlap.height / (box.width * box.height) if overlap else 0.0
                assert share <= MAX_LEGEND_SHARE, f"{which} {fig}: the legend covers {share:.0%} of a panel"
        plt.close(figure)
        checked += 1
    assert checked == len(config["figures"]) >= 18


def widening_texts(figure):
    """The titles and legend entries drawn beyond the figure's left or right edge, to name in a failure."""
    renderer, width = figure.canvas.get_renderer(), figure.get_figwidth() * figure.dpi
    texts = list(figure.texts) + [ax.title for ax in figure.axes]
    texts += [t for legend in [ax.get_legend() for ax in figure.axes] + list(figure.legends) if legend
              for t in legend.get_texts()]
    boxes = [(t, t.get_window_extent(renderer)) for t in texts if t.get_text()]
    return [t for t, box in boxes if box.x0 < 0 or box.x1 > width]


def test_shape_panels_share_one_scale(root, small_runs):
    """A fresh and a dried cell side by side (fig02): drawn at one scale, the dried cell looks smaller, as
    it is, and every wall stays inside its panel."""
    config = configs(root)["default"]
    cases = matrix.expand(config)
    names = matrix.figure_cases(config, "fig02", cases)
    runs = {n: small_runs[1.0 if cases[n].values["dryness"] == 1.0 else 0.5] for n in names}
    figure = shapes.draw(config, "fig02", runs, {n: cases[n] for n in names})
    panels = data_panels(figure)
    assert len({(ax.get_xlim(), ax.get_ylim()) for ax in panels}) == 1
    reach = panels[0].get_xlim()[1]
    widths = []
    for ax in panels:
        wall = np.concatenate([np.concatenate(c.get_segments()) for c in ax.collections if hasattr(c, "get_segments")])
        assert np.abs(wall).max() <= reach
        widths.append(np.ptp(wall[:, 0]))
    assert max(widths) / min(widths) > 1.05  # the dried cell is narrower at the end of drying
    plt.close(figure)
