"""This run's columns of the claims (config `claim_columns`; config/converged.yaml): a column is the paper's
claims (analysis/claims.py) evaluated over the cases at its axis values, `where` over base's. A column with
a `band` names the numerical changes that make it (each a set of axis values, whose cases ran at a few
dryness levels): the claims are evaluated again under each change, and the band is the range of the
values, beyond strain BAND_FROM only, where the column is judged on its value alone.

Under a change, a case whose changed counterpart ran is replaced by it (its curve and its summary row);
every other case of the column moves as the change moved the column's case of its dryness: its stresses
beyond BAND_FROM are multiplied by that case's ratio of smoothed stress, changed over unchanged, at each
strain (between dryness levels interpolated in log-ratio, outside them held). So a claim over turgor or
wall thickness gets the band its dryness levels measured, not none."""
import html

import numpy as np
import pandas as pd

from analysis import claims, comparison, matrix
from analysis.html_page import cell_text
from analysis.matrix import _same

BAND_FROM = 0.05  # nominal strain: up to it a column is judged on its value (issue 66: to 1 %), beyond it a band
STRESSES = ("plate_stress_Pa", "section_stress_Pa")
KEY = "claim_columns"


def specs(config):
    """{name: spec} of the config's claim columns, in their order ({} without `claim_columns`)."""
    return dict(config.get(KEY) or {})


def values_of(config, base, where):
    """A column's (or a change's) axis values: base's with `where` over them, and the values their coupled
    keys set (the closed cell's dt_ns is 100, level 3's 0.75)."""
    return matrix.build(config, {**base, **(where or {})})[1]


def matches(row, values, axes):
    """Whether a summary row (or a Case's values) has these axis values on `axes`."""
    return all(_same(row[a], values[a]) for a in axes)


def counterparts(config, summary, axes, change):
    """{case: its counterpart's case} for every summary row whose values, with `change` set (and what its
    coupled keys set), are another row's: the cases a change ran directly."""
    index = {tuple(_key(r[a]) for a in axes): r["case"] for _, r in summary.iterrows()}
    out = {}
    for _, r in summary.iterrows():
        values = values_of(config, {a: r[a] for a in axes}, change)
        moved = tuple(_key(values[a]) for a in axes)
        if moved in index and index[moved] != r["case"]:
            out[r["case"]] = index[moved]
    return out


def _key(value):
    return value if isinstance(value, str) else round(float(value), 12)


def stress_ratio(series, case, changed):
    """(grid strains, changed over unchanged smoothed plate stress) of two compressions; strains below
    BAND_FROM give 1."""
    g0, s0 = claims.stress_curve(series, case)
    g1, s1 = claims.stress_curve(series, changed)
    n = min(len(g0), len(g1))
    if n == 0:
        return np.array([]), np.array([])
    grid, ratio = g0[:n], s1[:n] / s0[:n]
    ratio = np.where(grid < BAND_FROM - 1e-12, 1.0, ratio)
    return grid, np.where(np.isfinite(ratio) & (ratio > 0), ratio, 1.0)


def ratio_at(ratios, dryness, strain):
    """The change's stress ratio at these strains for a case of this dryness, from {dryness: (grid, ratio)}
    of the column's measured pairs: interpolated in log-ratio between dryness levels, held outside them and
    beyond a grid's end; 1 below BAND_FROM."""
    strain = np.asarray(strain, dtype=float)
    levels = sorted(x for x, (grid, _) in ratios.items() if len(grid))
    if not levels:
        return np.ones_like(strain)
    logs = np.array([np.log(np.interp(strain, *ratios[x])) for x in levels])  # np.interp holds the ends
    if len(levels) == 1:
        out = np.exp(logs[0])
    else:
        out = np.exp(np.array([np.interp(dryness, levels, logs[:, k]) for k in range(len(strain))]))
    return np.where(strain < BAND_FROM - 1e-12, 1.0, out)


def changed_view(config, summary, series, column_values, change_values, axes):
    """(summary, series, {dryness: (grid, ratio)}) as the column reads under a change: counterparts in
    place of the cases that have one, every other case of the column moved by its dryness's ratio."""
    change = {a: v for a, v in change_values.items() if not _same(v, column_values[a])}
    own = [a for a in axes if a not in claims.PAPER_AXES]  # the axes that tell the columns apart
    column = set(summary[[matches(r, column_values, own) for _, r in summary.iterrows()]]["case"])
    direct = {c: o for c, o in counterparts(config, summary, axes, change).items() if c in column}
    at_base = [a for a in claims.PAPER_AXES if a != "dryness"]
    rows = summary.set_index("case")
    measured = {float(rows.loc[c, "dryness"]): stress_ratio(series, c, o) for c, o in direct.items()
                if matches(rows.loc[c], column_values, at_base)}
    # The summary: each counterpart's numbers under its original case's name and axis values.
    numbers = [c for c in summary.columns if c not in axes and c not in ("case", "studies")]
    replaced = summary.copy()
    for case, other in direct.items():
        replaced.loc[replaced["case"] == case, numbers] = rows.loc[other, numbers].to_numpy()
    # The series: the counterparts' records under the original names, the rest of the column moved.
    moved = series[~series["case"].isin(direct)].copy()
    for case in sorted(column - set(direct)):
        at = (moved["case"] == case) & (moved["stage"] == 1)
        if at.any():
            factor = ratio_at(measured, float(rows.loc[case, "dryness"]), moved.loc[at, "nominal_strain"].to_numpy())
            for stress in STRESSES:
                if stress in moved:
                    moved.loc[at, stress] = moved.loc[at, stress].to_numpy() * factor
    swapped = [series[series["case"] == other].assign(case=case) for case, other in direct.items()]
    return replaced, pd.concat([moved, *swapped], ignore_index=True), measured


def band_verdict(verdicts):
    """One verdict for a value and its band: the verdict all judged members share, or 'band spans the
    threshold' where they differ; 'not run' / 'not reached' as the value's where nothing was judged."""
    judged = {v for v in verdicts if v in ("agree", "disagree")}
    if len(judged) == 1:
        return judged.pop()
    return "band spans the threshold" if judged else verdicts[0]


def evaluate(config, summary, series, base):
    """{column name: rows}, each row a claims.evaluate row with `band_low`, `band_high`, `band_changes`
    (what made the band) and `column_verdict` (the verdict over value and band)."""
    axes = list(config["axes"])
    out = {}
    for name, spec in specs(config).items():
        values = values_of(config, base, spec.get("where"))
        rows = claims.evaluate(summary, values, series)
        under = {}
        for change_name, change in (spec.get("band") or {}).items():
            changed_summary, changed_series, _ = changed_view(config, summary, series, values,
                                                              values_of(config, values, change["where"]), axes)
            under[change["label"]] = claims.evaluate(changed_summary, values, changed_series)
        not_judged = spec.get("not_judged", {})
        for k, row in enumerate(rows):
            members = [row["value"]] + [r[k]["value"] for r in under.values()]
            finite = [m for m in members if np.isfinite(m)]
            row["band_low"] = min(finite) if len(finite) > 1 else np.nan
            row["band_high"] = max(finite) if len(finite) > 1 else np.nan
            row["band_changes"] = "; ".join(under)
            row["column_verdict"] = band_verdict([row["verdict"]] + [r[k]["verdict"] for r in under.values()])
            reason = not_judged.get(str(row["figure"]))
            if reason and row["verdict"] == "not run":
                row["column_verdict"] = f"not judged: {reason}"
        out[name] = rows
    return out


def long_table(columns):
    """The columns' rows as one table (tables/claim_columns.csv): a row per column and claim."""
    return pd.DataFrame([dict(row, column=name) for name, rows in columns.items() for row in rows])


def _cell(row):
    """A column's value, its band beyond strain BAND_FROM where it has one, and its verdict."""
    value = cell_text(row["value"])
    band = (f" <span class='band'>[{cell_text(row['band_low'])}, {cell_text(row['band_high'])}]</span>"
            if np.isfinite(row.get("band_low", np.nan)) else "")
    return f"<td>{value}{band}</td><td class='verdict'><b>{html.escape(row['column_verdict'])}</b></td>"


def section(config, columns, other_rows, other_label):
    """The report's claims in columns: the other run's (other_rows: its claims.csv, or None where it has
    not run), then this run's `claim_columns`, each value with its band and verdict; then in plain words
    which conclusions hold in every column, which change, and between which columns (and so why)."""
    spec = specs(config)
    names = list(columns)
    first = columns[names[0]]
    theirs = {(r["claim"], str(r["figure"])): r for r in (other_rows or [])}
    head = ("<table><tr><th>paper's claim</th><th>fig</th><th>measured</th><th>agree if</th>"
            f"<th colspan='2'>{html.escape(other_label)}</th>"
            + "".join(f"<th colspan='2'>{html.escape(spec[n]['label'])}</th>" for n in names) + "</tr>")
    body, verdicts = [], []
    for k, row in enumerate(first):
        o = theirs.get((row["claim"], str(row["figure"])))
        other_cells = (f"<td>{cell_text(o['value'])}</td><td class='verdict'><b>{html.escape(o['verdict'])}</b></td>"
                       if o else "<td></td><td class='verdict'>not run</td>")
        body.append(f"<tr><td>{html.escape(row['claim'])}</td><td>{row['figure']}</td><td>{html.escape(row['measured'])}"
                    f"</td><td>{html.escape(row['threshold'])}</td>{other_cells}"
                    + "".join(_cell(columns[n][k]) for n in names) + "</tr>")
        verdicts.append([o["verdict"] if o else "not run"] + [columns[n][k]["column_verdict"] for n in names])
    note = (f"<p>Each value is the claim's measure (analysis/claims.py); in brackets its band beyond strain "
            f"{BAND_FROM}, the range over the changes each column names: "
            + "; ".join(f"{html.escape(spec[n]['label'])}: {html.escape(first_row['band_changes'] or 'none')}"
                        for n, first_row in ((n, columns[n][0]) for n in names)) +
            ". A verdict holds over its band, or the band spans the threshold.</p>")
    return note + head + "".join(body) + "</table>" + plain_words(config, first, verdicts, other_label)


def plain_words(config, first, verdicts, other_label):
    """Which conclusions hold in every column that judges them, and which change between which columns,
    with what tells those columns apart (each column's `differs_from_previous`)."""
    spec = specs(config)
    labels = [other_label] + [spec[n]["label"] for n in spec]
    why = [""] + [spec[n].get("differs_from_previous", "") for n in spec]
    hold, change, undecided = [], [], []
    for row, vs in zip(first, verdicts):
        judged = [(i, v) for i, v in enumerate(vs) if v in ("agree", "disagree")]
        name = f"{html.escape(row['claim'])} (fig {row['figure']})"
        if any(v == "band spans the threshold" for v in vs):
            where = ", ".join(html.escape(labels[i]) for i, v in enumerate(vs) if v == "band spans the threshold")
            undecided.append(f"<li>{name}: its band spans the threshold in the {where}.</li>")
        if len(judged) >= 2 and len({v for _, v in judged}) == 1:
            hold.append(f"<li>{name}: {judged[0][1]} in all {len(judged)} columns that judge it.</li>")
        elif len({v for _, v in judged}) > 1:
            flips = [(a, b) for (a, va), (b, vb) in zip(judged, judged[1:]) if va != vb]
            text = "; ".join(f"{html.escape(labels[a])}: {vs[a]}, {html.escape(labels[b])}: {vs[b]}"
                             + "".join(f" ({html.escape(why[i])})" for i in range(a + 1, b + 1) if why[i])
                             for a, b in flips)
            change.append(f"<li>{name}: {text}.</li>")
    out = "<h3>In plain words</h3>"
    out += (f"<p><b>Hold in every column that judges them ({len(hold)}):</b></p><ul>{''.join(hold)}</ul>" if hold else
            "<p>No conclusion holds in every column that judges it.</p>")
    out += (f"<p><b>Change between columns ({len(change)}), with what tells the columns apart:</b></p>"
            f"<ul>{''.join(change)}</ul>" if change else "<p>No conclusion changes between the columns.</p>")
    if undecided:
        out += f"<p><b>Undecided by their band ({len(undecided)}):</b></p><ul>{''.join(undecided)}</ul>"
    return out


def counterpart_name(config, cases, case, where):
    """The case of `cases` ({name: Case}) with `case`'s axis values and `where` over them (and what their
    coupled keys set), or None."""
    wanted = values_of(config, case.values, where)
    return next((n for n, c in cases.items() if all(_same(c.values[a], wanted[a]) for a in wanted)), None)


def band_envelopes(config, summary, series, column_values, changes, axes, cases):
    """{case: (grid strains, low, high)} of each case's smoothed plate stress [kPa] over its column's band
    changes, from BAND_FROM on (empty where no change moves it); each change's view is made once."""
    views = [changed_view(config, summary, series, column_values,
                          values_of(config, column_values, change["where"]), axes)[1] for change in changes.values()]
    out = {}
    for case in cases:
        curves = [claims.stress_curve(view, case) for view in [series, *views]]
        n = min(len(g) for g, _ in curves)
        if n == 0 or len(curves) < 2:
            out[case] = (np.array([]), np.array([]), np.array([]))
            continue
        grid = curves[0][0][:n]
        stack = np.array([s[:n] for _, s in curves])
        keep = grid >= BAND_FROM - 1e-12
        out[case] = (grid[keep], stack.min(axis=0)[keep], stack.max(axis=0)[keep])
    return out


def default_cases(config, every):
    """The default target's cases of `every` ({name: Case}): the only ones a column reads."""
    return {n: every[n] for n in matrix.target_cases(config, every)}


def band_cases(config, every, cases, spec):
    """The cases a claim column's band reads for these cases: they, the column's cases of every dryness at
    the paper's base values, and those cases' counterparts under each change."""
    base = {axis: matrix.base_value(config, axis) for axis in config["axes"]}
    values = values_of(config, base, spec["where"])
    at_base = {a: values[a] for a in config["axes"] if a != "dryness"}
    names = set(cases) | {n for n, c in every.items() if matches(c.values, at_base, at_base)}
    for change in spec["band"].values():
        names |= {o for n in list(names) if (o := counterpart_name(config, every, every[n], change["where"]))}
    return names


def overlay_cases(config, fig, every, cases):
    """This run's cases a figure's overlay reads beyond its own (the `figure` rule's inputs): the claim
    columns' counterparts and the first column's band cases."""
    if not comparison.overlaid(config, fig):
        return set()
    every = default_cases(config, every)
    column_specs = list(specs(config).values())
    names = {o for spec in column_specs[1:] for n in cases
             if (o := counterpart_name(config, every, cases[n], spec["where"]))}
    if column_specs and column_specs[0].get("band"):
        names |= band_cases(config, every, cases, column_specs[0])
    return names - set(cases)
