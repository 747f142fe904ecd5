"""The paper's claims next to this run's numbers.

Claims about stress-strain curves are judged on the curves, not on one point: each case's compression
curve is smoothed (every grid strain gets the mean stress of all compression records within
+-SMOOTH_STRAIN of it) on a grid from START_STRAIN up to the strain both compared curves reach, and two
curves are compared by their relative RMS difference (RMS of the difference over RMS of their mean) or,
for "stiffer", by the ratio of their mean stresses (the ratio of the areas under them). The stress at
strain 0.05, which the verdicts used before, stays beside each verdict as `point_value`.

Every claim names the figure it comes from, what is measured, the threshold for "agree" and why; a
claim whose cases are not in the run (a reduced config) is "not run", and one whose curves are all there
but stop before the strains it compares (a reduced config's end strain) is "not reached"."""
import numpy as np

from analysis.aggregate import SMOOTH_STRAIN, loading_branch, window_mean

STRAIN = 0.05  # the strain of the point values kept beside the curve verdicts
# The paper's six axes, which the claims' cases vary; every other axis tells one configuration from another.
PAPER_AXES = ("dryness", "turgor_kPa", "plate_speed_m_s", "G_MPa", "t0_um", "D_um")
STRESS = f"stress_kPa_at_{STRAIN:.2f}"
GRID_STEP = 0.005
START_STRAIN = 0.02  # curves are compared from here on: below it the plates are still making contact
EARLY_STRAIN = 0.05  # "early" for the impulsive peaks of fast plates (Figs 11-12)
SERIES_COLUMNS = ["case", "stage", "nominal_strain", "plate_stress_Pa", "section_stress_Pa",
                  "plate_top_z_m"]  # what evaluate reads (the plate's height: a curve's loading branch)

METHOD = (f"Curves are compared on a strain grid (step {GRID_STEP}) from {START_STRAIN} up to the strain both "
          f"cases reach; each grid point is the mean plate stress of all compression records within "
          f"+-{SMOOTH_STRAIN} strain of it. 'relative RMS difference' is the RMS of the difference of two such "
          f"curves over the RMS of their mean; 'ratio of mean stresses' is the ratio of their means over the "
          f"common range. point_value is the older measure at strain {STRAIN} on the raw curves.")


def rows_at(summary, **values):
    """The summary's rows at these axis values (numbers compared to round-off, names exactly)."""
    rows = summary
    for axis, value in values.items():
        rows = rows[rows[axis] == value] if isinstance(value, str) else rows[np.isclose(rows[axis], value)]
    return rows


def _one(summary, column, **values):
    rows = rows_at(summary, **values)
    return float(rows[column].iloc[0]) if len(rows) else np.nan


def _spread(values):
    """Largest relative difference of a set of values to their mean."""
    v = np.asarray([x for x in values if np.isfinite(x)])
    return float(np.max(np.abs(v - v.mean())) / abs(v.mean())) if len(v) > 1 else np.nan


def stress_curve(series, case, column="plate_stress_Pa"):
    """(grid strains, smoothed stress in kPa) of one case's compression; empty if it has none."""
    c = loading_branch(series[(series["case"] == case) & (series["stage"] == 1)])
    e, s = c["nominal_strain"].to_numpy(), c[column].to_numpy() / 1e3
    if len(e) == 0 or not np.isfinite(e).any():
        return np.array([]), np.array([])
    grid = np.arange(START_STRAIN, np.nanmax(e) - SMOOTH_STRAIN + 1e-12, GRID_STEP)
    return grid, np.array([window_mean(e, s, g) for g in grid])


def _common(a, b, from_strain=START_STRAIN):
    (ga, sa), (gb, sb) = a, b
    n = min(len(ga), len(gb))
    keep = ga[:n] >= from_strain - 1e-12
    return sa[:n][keep], sb[:n][keep]


def relative_rms(a, b):
    """RMS of the difference of two curves over the RMS of their mean, on their common strains."""
    x, y = _common(a, b)
    if len(x) < 3:
        return np.nan
    return float(np.sqrt(np.mean((x - y) ** 2)) / np.sqrt(np.mean(((x + y) / 2) ** 2)))


def mean_ratio(a, b, from_strain=START_STRAIN):
    """Ratio of the mean stresses of two curves over their common strains (from from_strain on)."""
    x, y = _common(a, b, from_strain)
    return float(x.mean() / y.mean()) if len(x) >= 3 else np.nan


def early_peak_kPa(series, case):
    """Largest raw plate stress before EARLY_STRAIN: the impulsive peak of a fast plate."""
    c = series[(series["case"] == case) & (series["stage"] == 1)]
    early = c[c["nominal_strain"] <= EARLY_STRAIN]
    return float(early["plate_stress_Pa"].max() / 1e3) if len(early) else np.nan


def _nanmax(values):
    v = [x for x in values if np.isfinite(x)]
    return max(v) if v else np.nan


def _row(claim, figure, measured, value, agree, threshold, point_value=np.nan, note="", curves=()):
    """curves: the compression curves the claim compares, to tell a case missing from curves too short."""
    if np.isfinite(value):
        verdict = "agree" if agree(value) else "disagree"
    else:
        verdict = "not reached" if curves and all(len(grid) for grid, _ in curves) else "not run"
    return {"claim": claim, "figure": figure, "measured": measured, "value": value, "threshold": threshold,
            "verdict": verdict, "point_value": point_value, "note": note}


def evaluate(summary, base, series):
    """summary: the per-case table; base: the base axis values ({'turgor_kPa': 200, ...}); series: the
    time series (columns case, stage, nominal_strain, plate_stress_Pa, section_stress_Pa at least)."""
    b = dict(base)
    at = lambda **kw: {**{k: v for k, v in b.items() if k not in ("dryness",)}, **kw}  # noqa: E731
    empty = (np.array([]), np.array([]))

    def case_of(**values):
        rows = rows_at(summary, **at(**values))
        return rows["case"].iloc[0] if len(rows) else None

    def curve(column="plate_stress_Pa", **values):
        case = case_of(**values)
        return stress_curve(series, case, column) if case is not None else empty

    point = lambda **values: _one(summary, STRESS, **at(**values))  # noqa: E731
    rows = []

    by_dryness = {x: curve(dryness=x) for x in (1.0, 0.3, 0.1)}
    rows.append(_row("Fresh cells are stiffer than extremely dried ones (X/X0 = 1.0 vs 0.1, 200 kPa)", "7",
                     "ratio of mean stresses, fresh / X/X0 = 0.1", mean_ratio(by_dryness[1.0], by_dryness[0.1]),
                     lambda r: r > 1.0, "> 1", point(dryness=1.0) / point(dryness=0.1),
                     curves=[by_dryness[1.0], by_dryness[0.1]]))

    rows.append(_row("X/X0 = 0.1 stays above X/X0 = 0.3 at strains above 0.1", "7",
                     "ratio of mean stresses from strain 0.1 on, X/X0 = 0.1 / 0.3",
                     mean_ratio(by_dryness[0.1], by_dryness[0.3], from_strain=0.1),
                     lambda r: r > 1.0, "> 1", _one(summary, "stress_kPa_at_0.15", **at(dryness=0.1))
                     / _one(summary, "stress_kPa_at_0.15", **at(dryness=0.3)),
                     note="point_value here: at strain 0.15", curves=[by_dryness[0.1], by_dryness[0.3]]))

    fresh = {p: curve(dryness=1.0, turgor_kPa=p) for p in (100, 200, 300)}
    by_turgor = [mean_ratio(fresh[p], fresh[100]) for p in (100, 200, 300)]
    rows.append(_row("Fresh cells stiffen with turgor (100 < 200 < 300 kPa)", "10",
                     "ratio of mean stresses, 300 / 100 kPa (and 200 / 100 kPa between 1 and it)", by_turgor[2],
                     lambda r: 1.0 < by_turgor[1] < r, "> 1 and increasing",
                     point(dryness=1.0, turgor_kPa=300) / point(dryness=1.0, turgor_kPa=100),
                     curves=list(fresh.values())))

    dry = [curve(dryness=0.1, turgor_kPa=p) for p in (100, 200, 300)]
    rows.append(_row("Extremely dried cells barely depend on turgor (curves overlap)", "10",
                     "largest relative RMS difference of two turgor levels, X/X0 = 0.1",
                     _nanmax([relative_rms(dry[i], dry[j]) for i, j in ((0, 1), (0, 2), (1, 2))]),
                     lambda s: s < 0.15, "< 0.15", _spread([point(dryness=0.1, turgor_kPa=p) for p in (100, 200, 300)]),
                     curves=dry))

    peak = {x: _one(summary, "peak_force_top_uN", **at(dryness=x)) for x in (1.0, 0.1)}
    rows.append(_row("The plate force is largest for fresh cells", "14", "peak top-plate force, fresh / X/X0 = 0.1",
                     peak[1.0] / peak[0.1], lambda r: r > 1.0, "> 1", peak[1.0] / peak[0.1],
                     note="a peak over the whole curve: point_value is the same"))

    by_g = {(x, g): curve(dryness=x, G_MPa=g) for x in (1.0, 0.5, 0.1) for g in (0.18, 18)}
    g = [relative_rms(by_g[x, 0.18], by_g[x, 18]) for x in (1.0, 0.5, 0.1)]
    g_point = [abs(point(dryness=x, G_MPa=0.18) / point(dryness=x, G_MPa=18) - 1) for x in (1.0, 0.5, 0.1)]
    rows.append(_row("G = 18 and 0.18 MPa give virtually overlapping curves", "15",
                     "largest relative RMS difference, G 0.18 vs 18 MPa (3 dryness levels)", _nanmax(g),
                     lambda d: d < 0.10, "< 0.10", _nanmax(g_point), curves=list(by_g.values())))

    by_t = {(x, t): curve(dryness=x, t0_um=t) for x in (1.0, 0.5, 0.1) for t in (0.1, 1, 6, 12, 100)}
    thin = [relative_rms(by_t[x, t], by_t[x, 6]) for x in (1.0, 0.5, 0.1) for t in (0.1, 1, 12)]
    thin_point = [_spread([point(dryness=x, t0_um=t) for t in (0.1, 1, 6, 12)]) for x in (1.0, 0.5, 0.1)]
    rows.append(_row("Wall thickness 0.1 to 12 um makes no significant difference", "16",
                     "largest relative RMS difference to the 6 um wall (3 dryness levels)", _nanmax(thin),
                     lambda d: d < 0.10, "< 0.10", _nanmax(thin_point),
                     curves=[c for (x, t), c in by_t.items() if t != 100]))

    thick = [relative_rms(by_t[x, 100], by_t[x, 6]) for x in (1.0, 0.5, 0.1)]
    thick_point = [abs(point(dryness=x, t0_um=100) / point(dryness=x, t0_um=6) - 1) for x in (1.0, 0.5, 0.1)]
    rows.append(_row("A 100 um wall does change the response", "16",
                     "largest relative RMS difference, 100 vs 6 um (3 dryness levels)", _nanmax(thick),
                     lambda d: d > 0.10, "> 0.10", _nanmax(thick_point),
                     curves=[c for (x, t), c in by_t.items() if t in (6, 100)]))

    size_point = [abs(point(dryness=x, D_um=200) / point(dryness=x, D_um=150) - 1) for x in (1.0, 0.5, 0.1)]
    by_d = {(column, x, d): curve(column, dryness=x, D_um=d) for column in ("plate_stress_Pa", "section_stress_Pa")
            for x in (1.0, 0.5, 0.1) for d in (150, 200)}
    size = {column: _nanmax([relative_rms(by_d[column, x, 200], by_d[column, x, 150]) for x in (1.0, 0.5, 0.1)])
            for column in ("plate_stress_Pa", "section_stress_Pa")}
    holds = [c.split("_")[0] for c, d in size.items() if d < 0.25]
    closer = min(size, key=lambda c: size[c] if np.isfinite(size[c]) else np.inf).split("_")[0]
    supports = (f"the statement holds with the {' and the '.join(holds)} stress" if holds else
                f"neither definition supports the statement; the {closer} stress comes closer")
    for column, name in (("plate_stress_Pa", "plate stress (force / the fixed 150 x 150 um plate)"),
                         ("section_stress_Pa", "section stress (force / the cell's own section)")):
        rows.append(_row("D = 150 and 200 um cells respond closely alike", "18",
                         f"largest relative RMS difference of the {name}, 200 vs 150 um", size[column],
                         lambda d: d < 0.25, "< 0.25", _nanmax(size_point) if column == "plate_stress_Pa" else np.nan,
                         note=f"judged with both stress definitions: {supports}",
                         curves=[c for (col, x, d), c in by_d.items() if col == column]))

    peak_10 = {x: early_peak_kPa(series, case_of(dryness=x, plate_speed_m_s=10)) if case_of(dryness=x, plate_speed_m_s=10)
               else np.nan for x in (1.0, 0.1)}
    peak_1 = early_peak_kPa(series, case_of(dryness=1.0, plate_speed_m_s=1)) if case_of(dryness=1.0, plate_speed_m_s=1) \
        else np.nan
    rows.append(_row("Faster plates give impulsive early stress peaks, weaker for drier cells", "11-12",
                     f"largest stress before strain {EARLY_STRAIN}, 10 / 1 m/s, fresh", peak_10[1.0] / peak_1,
                     lambda r: r > 1.0 and peak_10[0.1] < peak_10[1.0],
                     f"> 1, and the 10 m/s peak lower at X/X0 = 0.1 ({peak_10[0.1]:.0f} kPa) than fresh "
                     f"({peak_10[1.0]:.0f} kPa)",
                     point(dryness=1.0, plate_speed_m_s=10) / point(dryness=1.0, plate_speed_m_s=1),
                     note="'weaker' read as the peak's size; relative to 1 m/s the dried peak is the larger"))

    # Our fresh cell is inflated by its turgor before the drying clock starts (the relaxation at rest),
    # and then stays as it is; V0 is that cell at rest, so its swelling is the relaxation's.
    grow = _one(summary, "settle_volume_ratio", **at(dryness=1.0))
    shrink = _one(summary, "dried_V_over_V0", **at(dryness=0.1))
    rows.append(_row("During drying the fresh cell swells slightly and dried cells shrink", "4",
                     "V at rest at its turgor / V as built, fresh (X/X0 = 0.1: V/V0 at the end of drying, "
                     "in 'threshold')", grow,
                     lambda v: v > 1.0 and shrink < 1.0, f"> 1 (X/X0 = 0.1: {shrink:.3f}, < 1)"))

    area, volume = (_one(summary, f"compression_{q}_change", **at(dryness=1.0)) for q in ("A", "V"))
    rows.append(_row("Area rises and volume falls slightly by the end of compression", "4",
                     "relative change of wall area over compression, fresh (of volume in 'threshold')", area,
                     lambda a: a > 0 and -0.05 < volume < 0, f"> 0 (volume: {volume:.3g}, between -0.05 and 0)"))

    steady = float(summary["drying_steady"].mean()) if "drying_steady" in summary.columns and len(summary) else np.nan
    latest = np.nan
    if {"drying_steady_time_us", "drying.steps", "time.dt_ns"} <= set(summary.columns) and len(summary):
        latest = float(np.nanmax(summary["drying_steady_time_us"] / (summary["drying.steps"] * summary["time.dt_ns"] / 1e3)))
    rows.append(_row("The drying transient settles early, then the cell stays steady", "4",
                     "share of cases whose drying ended at steady state before its cap", steady,
                     lambda s: s == 1.0, "1 (every case)",
                     note=f"the latest steady state came at {latest:.2f} of the cap"))

    # Fig 5's "fresh cells exhibit a minimum strain in the order of 0.035, dried 0.005-0.025" has two
    # readings; both are reported.
    wall = {x: _one(summary, "dried_wall_strain_mean", **at(dryness=x)) for x in (1.0, 0.1)}
    rows.append(_row("Fresh cells show a strain of about 0.035 (reading 1: mean wall bond strain)", "5",
                     "mean wall bond strain at the end of drying, fresh (X/X0 = 0.1 in 'threshold')", wall[1.0],
                     lambda s: 0.02 < s < 0.05, f"0.02 to 0.05 (X/X0 = 0.1: {wall[0.1]:.3g}, 0.005 to 0.025)",
                     note="two readings of the paper's sentence; see the next row"))
    dip = {x: _early_dip(series, case_of(dryness=x)) for x in (1.0, 0.1)}
    rows.append(_row("Fresh cells show a strain of about 0.035 (reading 2: early dip of the compression strain)",
                     "5", "deepest negative nominal strain early in compression, fresh (X/X0 = 0.1 in 'threshold')",
                     dip[1.0], lambda s: 0.02 < s < 0.05, f"0.02 to 0.05 (X/X0 = 0.1: {dip[0.1]:.3g}, 0.005 to 0.025)",
                     note="two readings of the paper's sentence; see the previous row"))
    return rows


def _early_dip(series, case):
    """Depth of the dip of the nominal strain below 0 before it first rises past EARLY_STRAIN."""
    if case is None:
        return np.nan
    c = series[(series["case"] == case) & (series["stage"] == 1)]
    e = c["nominal_strain"].to_numpy()
    if len(e) == 0:
        return np.nan
    rising = np.nonzero(e >= EARLY_STRAIN)[0]
    early = e[: rising[0]] if len(rising) else e
    return float(max(0.0, -np.nanmin(early))) if len(early) else np.nan
