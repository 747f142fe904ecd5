"""The sensitivity target's figures (issue 70): the Sobol indices beside the one-at-a-time shares, and the
emulators' check on the held-out runs. Four panels, one per answer, of one size."""
import numpy as np

from analysis import design, emulator
from analysis.figures.common import figure_title, grid, grid_with_legend, legend_below

COLOURS = {"first": "#1f77b4", "total": "#d62728", "one_at_a_time": "#7f7f7f"}


def factor_label(config, factor):
    return config["axes"][factor]["title"]


def draw_indices(config, table, answers):
    """Per answer, a bar per factor: first order and total (with their 95 % intervals) and the one-at-a-time
    share around the paper's baseline."""
    figure, panels, legend_axes = grid_with_legend(2, 2, 3, panel_w=4.4, panel_h=3.6)
    axes = [ax for row in panels for ax in row]
    for ax, (column, (label, transform, _unit)) in zip(axes, answers.items()):
        rows = table[table["answer"] == column]
        y = np.arange(len(rows))
        for k, (key, name) in enumerate((("first", "first order S_i"), ("total", "total order S_Ti"),
                                         ("one_at_a_time", "one at a time (paper's design)"))):
            values = rows[key].to_numpy()
            err = None
            if key != "one_at_a_time":
                err = np.vstack([values - rows[f"{key}_low"].to_numpy(), rows[f"{key}_high"].to_numpy() - values])
                err = np.maximum(err, 0.0)
            ax.barh(y + (k - 1) * 0.27, values, height=0.26, xerr=err, color=COLOURS[key], label=name,
                    error_kw={"lw": 0.8, "capsize": 1.5})
        ax.set_yticks(y, [factor_label(config, f) for f in rows["factor"]], fontsize=7)
        ax.invert_yaxis()
        ax.set_xlim(0, 1.05)
        ax.set_xlabel("share of the variance")
        ax.set_title(f"{'ln ' if transform == 'log' else ''}{label}", fontsize=9)
        ax.grid(axis="x", alpha=0.3)
    legend_below(legend_axes, axes)
    figure_title(figure, "Which factor moves the closed cell's answers: Sobol indices on the emulator (bars: "
                         "95 % bootstrap intervals), beside the one-at-a-time shares around the paper's baseline")
    return figure


def draw_held_out(frame, spec, emulators, answers, checks):
    """Per answer: the emulator's prediction (95 % band as a bar) against each held-out run, on the line of
    equality; its Q^2 and coverage in the panel's title."""
    figure, axes = grid(2, 2, panel_w=3.6, panel_h=3.4)
    held = frame[frame["role"] == "held_out"]
    x = design.unit_matrix(held, spec)
    for ax, (column, (label, transform, unit)) in zip(axes.ravel(), answers.items()):
        em = emulators[column]
        mean, sd = emulator.predict(em, x)
        run = held[column].to_numpy(dtype=float)
        middle = emulator.backward(mean, transform)
        low = emulator.backward(mean - emulator.Z95 * sd, transform)
        high = emulator.backward(mean + emulator.Z95 * sd, transform)
        ax.errorbar(run, middle, yerr=[middle - low, high - middle], fmt="o", ms=3, lw=0.7, color="#1f77b4")
        span = [min(run.min(), low.min()), max(run.max(), high.max())]
        ax.plot(span, span, "k--", lw=0.8)
        if transform == "log":
            ax.set_xscale("log")
            ax.set_yscale("log")
        check = checks[checks["answer"] == column].iloc[0]
        ax.set_title(f"{label}: Q2 = {check['q2']:.3f}, {100 * check['coverage_95']:.0f} % in band", fontsize=8)
        ax.set_xlabel(f"held-out run [{unit}]")
        ax.set_ylabel(f"emulator [{unit}]")
        ax.grid(alpha=0.3)
    figure_title(figure, f"The emulators on {len(held)} held-out runs they never saw (bars: 95 % bands)")
    return figure
