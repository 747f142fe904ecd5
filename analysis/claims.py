"""The paper's claims next to this run's numbers, each computed from the summary table.

Every claim names the figure it comes from, what is measured, the threshold for "agree" and
why; a claim whose cases are not in the run (a reduced config) is "not run"."""
import numpy as np

STRAIN = 0.05  # the nominal strain at which stresses are compared (every run reaches it)
STRESS = f"stress_kPa_at_{STRAIN:.2f}"


def _pick(summary, **values):
    rows = summary
    for axis, value in values.items():
        rows = rows[np.isclose(rows[axis], value)]
    return rows


def _one(summary, column, **values):
    rows = _pick(summary, **values)
    return float(rows[column].iloc[0]) if len(rows) else np.nan


def _spread(values):
    """Largest relative difference of a set of values to their mean."""
    v = np.asarray([x for x in values if np.isfinite(x)])
    return float(np.max(np.abs(v - v.mean())) / abs(v.mean())) if len(v) > 1 else np.nan


def _row(claim, figure, measured, value, agree, threshold):
    verdict = "not run" if not np.isfinite(value) else ("agree" if agree(value) else "disagree")
    return {"claim": claim, "figure": figure, "measured": measured, "value": value, "threshold": threshold,
            "verdict": verdict}


def evaluate(summary, base):
    """summary: the per-case table; base: the base axis values ({'turgor_kPa': 200, ...})."""
    b = dict(base)
    at = lambda **kw: {**{k: v for k, v in b.items() if k not in ("dryness",)}, **kw}  # noqa: E731
    rows = []

    fresh, dry = _one(summary, STRESS, **at(dryness=1.0)), _one(summary, STRESS, **at(dryness=0.1))
    rows.append(_row("Fresh cells are stiffer than extremely dried ones (X/X0 = 1.0 vs 0.1, 200 kPa)", "7",
                     f"ratio of plate stress at strain {STRAIN}", fresh / dry, lambda r: r > 1.0, "> 1"))

    by_turgor = [_one(summary, STRESS, **at(dryness=1.0, turgor_kPa=p)) for p in (100, 200, 300)]
    rows.append(_row("Fresh cells stiffen with turgor (100 < 200 < 300 kPa)", "10",
                     f"stress at strain {STRAIN} for 300 kPa / 100 kPa", by_turgor[2] / by_turgor[0],
                     lambda r: r > 1.0 and by_turgor[0] < by_turgor[1] < by_turgor[2],
                     "> 1 and increasing"))

    dry_turgor = [_one(summary, STRESS, **at(dryness=0.1, turgor_kPa=p)) for p in (100, 200, 300)]
    rows.append(_row("Extremely dried cells barely depend on turgor (curves overlap)", "10",
                     f"largest relative spread of stress at strain {STRAIN}, X/X0 = 0.1", _spread(dry_turgor),
                     lambda s: s < 0.15, "< 0.15"))

    peak = {x: _one(summary, "peak_force_top_uN", **at(dryness=x)) for x in (1.0, 0.5, 0.1)}
    rows.append(_row("The plate force is largest for fresh cells", "14", "peak top-plate force, fresh / X/X0 = 0.1",
                     peak[1.0] / peak[0.1], lambda r: r > 1.0, "> 1"))

    g = [_one(summary, STRESS, **at(dryness=x, G_MPa=v)) for x in (1.0, 0.5, 0.1) for v in (0.18, 18)]
    g_diff = max(abs(g[i] - g[i + 1]) / abs(g[i + 1]) for i in (0, 2, 4)) if all(np.isfinite(g)) else np.nan
    rows.append(_row("G = 18 and 0.18 MPa give virtually overlapping curves", "15",
                     f"largest relative difference of stress at strain {STRAIN} (3 dryness levels)", g_diff,
                     lambda d: d < 0.10, "< 0.10"))

    thin = [_spread([_one(summary, STRESS, **at(dryness=x, t0_um=t)) for t in (0.1, 1, 6, 12)]) for x in (1.0, 0.5, 0.1)]
    rows.append(_row("Wall thickness 0.1 to 12 um makes no significant difference", "16",
                     f"largest relative spread of stress at strain {STRAIN}", max(thin) if all(np.isfinite(thin)) else np.nan,
                     lambda d: d < 0.10, "< 0.10"))

    thick = [abs(_one(summary, STRESS, **at(dryness=x, t0_um=100)) / _one(summary, STRESS, **at(dryness=x, t0_um=6)) - 1)
             for x in (1.0, 0.5, 0.1)]
    rows.append(_row("A 100 um wall does change the response", "16",
                     f"largest relative change of stress at strain {STRAIN}, 100 vs 6 um", np.nanmax(thick) if np.any(np.isfinite(thick)) else np.nan,
                     lambda d: d > 0.10, "> 0.10"))

    size = [abs(_one(summary, STRESS, **at(dryness=x, D_um=200)) / _one(summary, STRESS, **at(dryness=x, D_um=150)) - 1)
            for x in (1.0, 0.5, 0.1)]
    rows.append(_row("D = 150 and 200 um cells respond closely alike", "18",
                     f"largest relative difference of stress at strain {STRAIN}", np.nanmax(size) if np.any(np.isfinite(size)) else np.nan,
                     lambda d: d < 0.25, "< 0.25"))

    speeds = [_one(summary, "stress_kPa_at_0.05", **at(dryness=1.0, plate_speed_m_s=v)) for v in (1, 10)]
    rows.append(_row("Faster plates give higher (inertial) stresses at low strain", "11",
                     f"stress at strain {STRAIN}, 10 m/s / 1 m/s, fresh", speeds[1] / speeds[0],
                     lambda r: r > 1.0, "> 1"))

    # Our fresh cell is inflated by its turgor before the drying clock starts (the relaxation at rest),
    # and then stays as it is; V0 is that cell at rest, so its swelling is the relaxation's.
    grow = _one(summary, "settle_volume_ratio", **at(dryness=1.0))
    shrink = _one(summary, "dried_V_over_V0", **at(dryness=0.1))
    rows.append(_row("During drying the fresh cell swells slightly and dried cells shrink", "4",
                     "V at rest at its turgor / V as built, fresh (X/X0 = 0.1: V/V0 at the end of drying, "
                     "in 'threshold')", grow,
                     lambda v: v > 1.0 and shrink < 1.0, f"> 1 (X/X0 = 0.1: {shrink:.3f}, < 1)"))

    strain_fresh = _one(summary, "end_wall_strain_mean", **at(dryness=1.0))
    rows.append(_row("Fresh cells show a wall strain of about 0.035", "5",
                     "mean wall bond strain at the end of compression, fresh", strain_fresh,
                     lambda s: 0.02 < s < 0.05, "0.02 to 0.05"))
    return rows
