"""The calibrate target's figures (issue 70): the posterior of the unknowns (each marginal over its prior
range, the baseline's value marked, and the joint samples of the two the data inform most), and the posterior predictive of
each target beside the measured value."""
import numpy as np

from analysis import design
from analysis.figures.common import figure_title, grid

PAPER_COLOUR, POSTERIOR_COLOUR, PRIOR_COLOUR = "#d62728", "#1f77b4", "#7f7f7f"
QUANTITY_LABELS = {"volumetric_modulus_MPa": "eps = V dP/dV [MPa]", "dried_V_over_V0": "V/V0 at the end of drying",
                   "stress_kPa": "plate stress [kPa]"}


def axis_scale(ax, spec, which="x"):
    if spec.get("scale") == "log":
        (ax.set_xscale if which == "x" else ax.set_yscale)("log")


def bins_of(spec, n=40):
    low, high = spec["range"]
    return np.geomspace(low, high, n + 1) if spec.get("scale") == "log" else np.linspace(low, high, n + 1)


def most_informed(samples, unknowns, factor_specs):
    """The two unknowns whose 90 % intervals take the smallest share of their prior ranges (in the unit
    coordinate of the design: the log for log-scale factors), the first first."""
    def share(u):
        low, high = np.percentile([design.factor_to_unit(v, factor_specs[u]) for v in samples[u]], [5, 95])
        return high - low
    ranked = sorted(unknowns, key=share)
    return (ranked[0], ranked[1]) if len(ranked) > 1 else (ranked[0], ranked[0])


def draw_posterior(config, samples, unknowns, factor_specs, baseline):
    """One panel per unknown (its marginal; the prior's flat density as a grey line) and one of the joint
    samples of the two the data inform most. baseline: {unknown: config base's value} (the paper's wall, in red)."""
    figure, axes = grid(1, len(unknowns) + 1, panel_w=3.2, panel_h=3.0)
    for ax, u in zip(axes[0], unknowns):
        spec = factor_specs[u]
        bins = bins_of(spec)
        ax.hist(samples[u], bins=bins, density=False, weights=np.full(len(samples), 1.0 / len(samples)),
                color=POSTERIOR_COLOUR, alpha=0.7, label="posterior")
        ax.hlines(1.0 / (len(bins) - 1), bins[0], bins[-1], color=PRIOR_COLOUR, lw=1.5, label="prior")
        ax.axvline(baseline[u], color=PAPER_COLOUR, lw=1.5, label="the baseline (the paper's; c ours)")
        axis_scale(ax, spec)
        ax.set_xlim(bins[0], bins[-1])
        ax.set_xlabel(config["axes"][u]["title"])
        ax.set_ylabel("share of the samples per bin")
        ax.grid(alpha=0.3)
    ax = axes[0][-1]
    a, b = most_informed(samples, unknowns, factor_specs)
    pick = samples.sample(min(3000, len(samples)), random_state=1)
    ax.scatter(pick[a], pick[b], s=2, color=POSTERIOR_COLOUR, alpha=0.3)
    ax.plot(baseline[a], baseline[b], "*", color=PAPER_COLOUR, ms=12, clip_on=False)  # G's 18 is its range's edge
    axis_scale(ax, factor_specs[a], "x")
    axis_scale(ax, factor_specs[b], "y")
    ax.set_xlim(*factor_specs[a]["range"])
    ax.set_ylim(*factor_specs[b]["range"])
    ax.set_xlabel(config["axes"][a]["title"])
    ax.set_ylabel(config["axes"][b]["title"])
    ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7)
    figure_title(figure, "The wall's unknowns given the measured numbers: the posterior (blue) over the prior "
                         "(grey), the paper's values in red (c: ours)")
    return figure


def draw_predictive(predictive, prior_runs, labels):
    """One panel per target column: the measured value's 90 % interval, the posterior predictive's 5-95 %,
    and the design's runs (the prior's spread), on a log axis where the target is given in the log."""
    figure, axes = grid(1, len(predictive), panel_w=3.0, panel_h=3.2)
    for ax, (_, row) in zip(axes[0], predictive.iterrows()):
        runs = prior_runs[row["column"]].to_numpy(dtype=float)
        ax.plot(np.full(len(runs), 0.0), runs, "_", color=PRIOR_COLOUR, ms=14, alpha=0.6)
        ax.errorbar([1.0], [row["measured"]], yerr=[[row["measured"] - row["measured_p05"]],
                                                    [row["measured_p95"] - row["measured"]]],
                    fmt="s", color="black", capsize=4)
        ax.errorbar([2.0], [row["predicted_median"]], yerr=[[row["predicted_median"] - row["predicted_p05"]],
                                                            [row["predicted_p95"] - row["predicted_median"]]],
                    fmt="o", color=POSTERIOR_COLOUR, capsize=4)
        ax.set_xticks([0, 1, 2], ["design runs\n(prior)", "measured\n(90 %)", "posterior\npredictive (90 %)"], fontsize=7)
        ax.set_xlim(-0.6, 2.6)
        if row.get("scale") == "log":
            ax.set_yscale("log")
        ax.set_title(labels.get(row["target"], row["target"]), fontsize=8)
        quantity = row["column"].split("@")[0]
        ax.set_ylabel(QUANTITY_LABELS.get("stress_kPa" if quantity.startswith("stress") else quantity, quantity))
        ax.grid(alpha=0.3)
    figure_title(figure, "Each target: what the design's runs spanned, what was measured, and what the posterior predicts")
    return figure
