"""Ensembles of seeded heterogeneous cells (docs/model.md §3c): the members of an ensemble are the cases
that differ only in their seed. Their curves are put on one grid and drawn as the mean with the 10th-90th
percentile band (figures with `band:`); their summary numbers are given as mean and band; the paper's
claims that an ensemble study covers are judged on the mean curves, with the band of the members'
values beside the verdict."""
import numpy as np
import pandas as pd

from analysis import claims
from analysis.aggregate import rows_of

BAND_PERCENTILES = (10, 90)
GRID_POINTS = 200
SEED_AXIS = "seed"


def rising(x, y):
    """The part of a curve up to its largest x (a loading branch), finite, with x strictly rising (a
    record that does not advance x is dropped), so that it can be interpolated."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    keep = np.isfinite(x) & np.isfinite(y)
    x, y = x[keep], y[keep]
    if not len(x):
        return x, y
    x, y = x[: int(np.argmax(x)) + 1], y[: int(np.argmax(x)) + 1]
    advancing = np.concatenate([[True], x[1:] > np.maximum.accumulate(x)[:-1]])
    return x[advancing], y[advancing]


def band(members, points=GRID_POINTS):
    """members: [(x, y)] of one ensemble. Returns (grid, mean, low, high) over the x range every member
    reaches (empty arrays if none is shared): the members interpolated on the grid, their mean and
    their BAND_PERCENTILES."""
    curves = [rising(x, y) for x, y in members]
    curves = [(x, y) for x, y in curves if len(x) >= 2]
    if not curves:
        return (np.array([]),) * 4
    start, stop = max(x[0] for x, _ in curves), min(x[-1] for x, _ in curves)
    if not stop > start:
        return (np.array([]),) * 4
    grid = np.linspace(start, stop, points)
    values = np.array([np.interp(grid, x, y) for x, y in curves])
    low, high = np.percentile(values, BAND_PERCENTILES, axis=0)
    return grid, values.mean(axis=0), low, high


def members_of(rows, axes):
    """{values of the other axes: rows} for the rows of one ensemble study: cases that differ only in
    their seed are one ensemble."""
    others = [a for a in axes if a != SEED_AXIS]
    return {key if isinstance(key, tuple) else (key,): group for key, group in rows.groupby(others)}


def _band_of(values):
    v = np.asarray([x for x in values if np.isfinite(x)])
    if not len(v):
        return np.nan, np.nan, np.nan
    low, high = np.percentile(v, BAND_PERCENTILES)
    return float(v.mean()), float(low), float(high)


ENSEMBLE_QUANTITIES = {  # summary column -> what the table calls it
    "smoothed_stress_kPa_at_0.05": "stress at 0.05 [kPa]",
    "smoothed_stress_kPa_at_0.10": "stress at 0.10 [kPa]",
    "peak_force_top_uN": "peak force [uN]",
    "dried_V_over_V0": "V/V0 dried",
}


def ensemble_table(config, summary, study, reference=None):
    """One row per ensemble of `study` (per value of its other axes) and quantity: the members, their
    mean, band and coefficient of variation; `reference`: the homogeneous cells' summary rows, whose
    value at the same dryness stands beside the mean."""
    axes = list(config["studies"][study]["vary"])
    rows = rows_of(summary, study)
    out = []
    for key, group in members_of(rows, axes).items():
        ensemble = {a: v for a, v in zip([a for a in axes if a != SEED_AXIS], key)}
        same = _reference_at(reference, ensemble["dryness"]) if "dryness" in ensemble else None
        for column, name in ENSEMBLE_QUANTITIES.items():
            mean, low, high = _band_of(group[column])
            out.append({**ensemble, "members": len(group), "quantity": name, "mean": mean,
                        f"{BAND_PERCENTILES[0]}th-{BAND_PERCENTILES[1]}th": f"{low:.4g} to {high:.4g}",
                        "CV of members": float(group[column].std() / mean) if mean else np.nan,
                        "homogeneous": float(same[column]) if same is not None else np.nan})
    return pd.DataFrame(out)


def _mean_curve(series, cases):
    """The mean of the members' smoothed stress curves (claims.stress_curve) over the strains all reach."""
    curves = [claims.stress_curve(series, c) for c in cases]
    curves = [c for c in curves if len(c[0])]
    if not curves:
        return np.array([]), np.array([])
    n = min(len(g) for g, _ in curves)
    return curves[0][0][:n], np.mean([s[:n] for _, s in curves], axis=0)


def ensemble_claims(config, summary, series, study="ensemble", reference=None):
    """The paper's claims an ensemble of fresh and X/X0 = 0.1 cells covers (Figs 7 and 14), judged on the
    ensemble's mean curves; the band is that of the same measure on each seed's pair of cells."""
    rows = rows_of(summary, study)
    by_dryness = {x: g for x, g in rows.groupby("dryness")}
    if not {1.0, 0.1} <= set(by_dryness):
        return pd.DataFrame()
    fresh, dry = by_dryness[1.0].set_index(SEED_AXIS), by_dryness[0.1].set_index(SEED_AXIS)
    seeds = sorted(set(fresh.index) & set(dry.index))
    ref_fresh, ref_dry = _reference_at(reference, 1.0), _reference_at(reference, 0.1)
    both = ref_fresh is not None and ref_dry is not None
    curve = lambda case: claims.stress_curve(series, case)  # noqa: E731
    stiffer = [claims.mean_ratio(curve(fresh.loc[s, "case"]), curve(dry.loc[s, "case"])) for s in seeds]
    out = [_claim_row("Fresh cells are stiffer than extremely dried ones (X/X0 = 1.0 vs 0.1)", "7",
                      "ratio of mean stresses, fresh / X/X0 = 0.1",
                      claims.mean_ratio(_mean_curve(series, fresh.loc[seeds, "case"]),
                                        _mean_curve(series, dry.loc[seeds, "case"])), stiffer,
                      claims.mean_ratio(curve(ref_fresh["case"]), curve(ref_dry["case"])) if both else np.nan,
                      lambda r: r > 1.0, "> 1")]
    peak = "peak_force_top_uN"
    out.append(_claim_row("The plate force is largest for fresh cells", "14", "peak top-plate force, fresh / X/X0 = 0.1",
                          fresh.loc[seeds, peak].mean() / dry.loc[seeds, peak].mean(),
                          [fresh.loc[s, peak] / dry.loc[s, peak] for s in seeds],
                          ref_fresh[peak] / ref_dry[peak] if both else np.nan, lambda r: r > 1.0, "> 1"))
    return pd.DataFrame(out)


def _reference_at(reference, dryness):
    """The homogeneous cell's summary row at this dryness, or None."""
    if reference is None:
        return None
    same = reference[np.isclose(reference["dryness"], dryness)]
    return same.iloc[0] if len(same) else None


def _claim_row(claim, figure, measured, on_mean, per_member, homogeneous, agree, threshold):
    _, low, high = _band_of(per_member)
    members = [m for m in per_member if np.isfinite(m)]
    return {"claim": claim, "figure": figure, "measured": measured, "threshold": threshold,
            "value on the mean": on_mean,
            f"members' {BAND_PERCENTILES[0]}th-{BAND_PERCENTILES[1]}th": f"{low:.3g} to {high:.3g}",
            "members agreeing": f"{sum(agree(m) for m in members)} of {len(members)}",
            "homogeneous cell": homogeneous,
            "verdict": ("agree" if agree(on_mean) else "disagree") if np.isfinite(on_mean) else "not run"}


def band_growth(config, summary, study="ensemble_spread", strains=("0.05", "0.10")):
    """How the band grows with the coefficient of variation: per value of the spread axis and strain, the
    mean stress, the band's width over it, and the members' own coefficient of variation."""
    rows = rows_of(summary, study)
    out = []
    for spread, group in rows.groupby("spread"):
        for strain in strains:
            stress = group[f"smoothed_stress_kPa_at_{strain}"]
            mean, low, high = _band_of(stress)
            out.append({"CV of the properties": spread, "members": len(group), "strain": float(strain),
                        "mean stress [kPa]": mean, "band width / mean": (high - low) / mean if mean else np.nan,
                        "CV of the members' stress": float(stress.std() / mean) if mean else np.nan})
    return pd.DataFrame(out)
