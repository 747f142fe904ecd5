"""Shared figure helpers: axis titles, value labels, ordering, saving."""
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


def unit_suffix(config, axis):
    title = axis_title(config, axis)
    return " " + title[title.index("[") + 1:title.index("]")] if "[" in title else ""


def moment_label(moment):
    if moment == "end_of_drying":
        return "end of drying"
    if moment == "end":
        return "end of compression"
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


def panel_letter(index):
    return "(" + "abcdefghijklmnopqrstuvwxyz"[index] + ")"


def save(figure, png, pdf):
    figure.savefig(png, dpi=130, bbox_inches="tight")
    figure.savefig(pdf, bbox_inches="tight")
    plt.close(figure)
