"""The sensitivity target's analysis (issue 70): emulators of the design's answers, checked on the held-out
runs; Sobol indices with bootstrap intervals beside the paper's one-at-a-time shares; the slider page's data.

The four answers of the issue are emulated and decomposed: the stress at strains 0.05 and 0.10 and eps in
their logarithms (their indices apportion relative changes: G alone spans two decades), the dried V/V0 as it
is. The stress at 0.02 to 0.20 is emulated for the slider page's curve.
"""
import numpy as np
import pandas as pd

from analysis import design, emulator, sobol
from analysis.matrix import base_value
from analysis.design_runs import STRAINS, STRESS_OUTPUTS, stress_column

ANSWERS = {  # column: (label, transform, unit)
    stress_column(0.05): ("stress at strain 0.05", "log", "kPa"),
    stress_column(0.10): ("stress at strain 0.10", "log", "kPa"),
    "dried_V_over_V0": ("dried V/V0", "none", "1"),
    "volumetric_modulus_MPa": ("eps = V dP/dV", "log", "MPa"),
}
SOBOL_POINTS = 8192      # base points of the Saltelli scheme on the emulator
BOOTSTRAP = 40           # emulators refitted on resampled runs: the indices' intervals
BOOTSTRAP_POINTS = 2048
OAT_DRYNESS = 0.5        # the paper's one-at-a-time sweeps around its baseline, at X/X0 = 0.5


def transform_of(column):
    return ANSWERS[column][1] if column in ANSWERS else "log"


def fit_all(frame, spec, columns):
    """{column: emulator} fitted on the training runs."""
    train = frame[frame["role"] == "train"]
    x = design.unit_matrix(train, spec)
    return {c: emulator.fit(x, train[c].to_numpy(), transform_of(c)) for c in columns}


def held_out_table(frame, spec, emulators):
    """One row per emulated answer: Q^2, RMSE and coverage of the 95 % band on the held-out runs."""
    held = frame[frame["role"] == "held_out"]
    x = design.unit_matrix(held, spec)
    rows = []
    for column, em in emulators.items():
        check = emulator.held_out_check(em, x, held[column].to_numpy())
        rows.append({"answer": column, "emulated_as": "ln" if em["transform"] == "log" else "value", **check})
    return pd.DataFrame(rows)


def baseline_unit(config, spec):
    """The paper's baseline (config base) at X/X0 = 0.5 as a point of the unit cube, each factor clipped
    into its range (K's base 20 MPa and k_wc's 10^4 N/m lie inside theirs)."""
    point = []
    for factor, fspec in spec["factors"].items():
        value = OAT_DRYNESS if factor == "dryness" else base_value(config, factor)
        point.append(min(1.0, max(0.0, design.factor_to_unit(value, fspec))))
    return np.array(point)


def centred_interval(estimate, replicates):
    """The 95 % interval of the replicates' spread about their own mean, centred on the estimate: a resample
    repeats some runs, which shifts the replicates' indices alike, enough to leave a near-zero estimate
    outside a plain percentile interval; the spread is the uncertainty, the shift is not."""
    centre = replicates.mean(axis=0)
    return (estimate + np.percentile(replicates, 2.5, axis=0) - centre,
            estimate + np.percentile(replicates, 97.5, axis=0) - centre)


def sobol_table(config, frame, spec, emulators, seed=11):
    """Per answer and factor: the first and total Sobol indices of the emulator's mean, their 95 % intervals
    (the spread of BOOTSTRAP emulators refitted, kernel kept, on runs drawn with replacement, each with its
    own Sobol sequence: centred_interval), and the one-at-a-time share around the paper's baseline."""
    train = frame[frame["role"] == "train"]
    x = design.unit_matrix(train, spec)
    factors = list(spec["factors"])
    rng = np.random.default_rng(seed)
    rows = []
    base = baseline_unit(config, spec)
    for column in ANSWERS:
        em = emulators[column]
        first, total = sobol.indices(lambda u: emulator.predict_mean(em, u), len(factors), SOBOL_POINTS, seed)
        replicates = []
        for b in range(BOOTSTRAP):
            pick = rng.integers(0, len(train), len(train))
            replica = emulator.refit(em, x[pick], train[column].to_numpy()[pick])
            replicates.append(sobol.indices(lambda u: emulator.predict_mean(replica, u), len(factors),
                                            BOOTSTRAP_POINTS, seed + 1 + b))
        firsts, totals = np.array([r[0] for r in replicates]), np.array([r[1] for r in replicates])
        oat = sobol.one_at_a_time(lambda u: emulator.predict_mean(em, u), base)
        first_low, first_high = centred_interval(first, firsts)
        total_low, total_high = centred_interval(total, totals)
        for i, factor in enumerate(factors):
            rows.append({"answer": column, "factor": factor, "first": first[i], "first_low": first_low[i],
                         "first_high": first_high[i], "total": total[i], "total_low": total_low[i],
                         "total_high": total_high[i], "one_at_a_time": oat[i]})
    return pd.DataFrame(rows)


def page_data(config, study, spec, emulators):
    """What the slider page computes from: each factor's range, scale, baseline and label; the strains; an
    emulator per strain (as_json of analysis/emulator.py)."""
    axes = config["axes"]
    return {"study": study, "strains": list(STRAINS),
            "factors": [{"name": f, "title": axes[f]["title"], "range": list(s["range"]),
                         "scale": s.get("scale", "linear"), "base": base_value(config, f)}
                        for f, s in spec["factors"].items()],
            "emulators": [emulator.as_json(emulators[c]) for c in STRESS_OUTPUTS]}


def predicted_curve(spec, emulators, values):
    """The emulators' stress curve (kPa) at one setting {factor: value}: median and 95 % band per strain."""
    u = np.array([[design.factor_to_unit(values[f], s) for f, s in spec["factors"].items()]])
    rows = []
    for strain, column in zip(STRAINS, STRESS_OUTPUTS):
        mean, sd = emulator.predict(emulators[column], u)
        rows.append({"strain": strain, "median_kPa": float(np.exp(mean[0])),
                     "low_kPa": float(np.exp(mean[0] - emulator.Z95 * sd[0])),
                     "high_kPa": float(np.exp(mean[0] + emulator.Z95 * sd[0]))})
    return pd.DataFrame(rows)
