"""This run beside another (config `compare_with`, e.g. config/converged.yaml beside the paper's
configuration in results/): every claim's verdict and value in both runs, which conclusions changed,
and the other run's curves for the figures it names. The same physical case is the other run's case of
the same study with the same values of the axes the study varies (the numerics are in `base`; a case whose
numerics put another value in its name here, as the thickest wall's time step, is still found)."""
import html
import os

import numpy as np
import pandas as pd

from analysis import provenance
from analysis.html_page import cell_text


KEY = "compare_with"


def other(config):
    """(the other run's output_dir, its label, this run's label), or None without `compare_with`."""
    spec = config.get(KEY)
    return (spec["output_dir"], spec["label"], spec["this_run"]) if spec else None


def other_claims_file(config):
    spec = other(config)
    return f"{spec[0]}/tables/claims.csv" if spec else None


def other_made_by(config):
    """(the other run's recorded version and commit, or None, and whether it is not this checkout's):
    its tables/provenance.json against this code's (analysis/provenance.py)."""
    spec = other(config)
    made = provenance.read(f"{spec[0]}/tables/provenance.json") if spec else None
    return made, made != provenance.record()


def made_by_note(config):
    """A warning on the page where the other run's folder is missing, has no record of the code that made
    it, or was made by other code than this run's: which run, which version and commit."""
    spec = other(config)
    if not spec or not os.path.exists(other_claims_file(config)):
        return ""
    made, differs = other_made_by(config)
    if not differs:
        return ""
    this = provenance.line()
    if made is None:
        what = "has no record of the code that made it (no tables/provenance.json: made before 0.3.0)"
    else:
        what = f"was made by cellsim {made['version']}, commit {made['commit']}"
    return (f"<div class='warning'><b>The {html.escape(spec[1])} in <code>{html.escape(spec[0])}</code> {html.escape(what)}"
            f"</b>, this run by {html.escape(this)}. Its claims and its dashed curves below are that run's: "
            f"run <code>snakemake --cores 2</code> again with this checkout to compare like with like.</div>")


def overlaid(config, fig):
    """Whether the figure draws the other run's curves (dashed) beside this run's."""
    return bool(config.get(KEY)) and fig in config[KEY].get("figures", [])


def other_runs(config, cases):
    """{case: result path} of the other run's results of these cases ({name: Case}), those that exist: for
    each, the other run's case of one of its studies with the same values of the axes that study varies
    (the other run's manifest.csv); by name where the other run has no manifest or no such case."""
    spec = other(config)
    if not spec:
        return {}
    manifest_path = f"{spec[0]}/manifest.csv"
    manifest = pd.read_csv(manifest_path) if os.path.exists(manifest_path) else None
    out = {}
    for name, case in cases.items():
        path = (same_case(config, manifest, case) if manifest is not None else None) or f"{spec[0]}/runs/{name}.h5"
        if os.path.exists(path):
            out[name] = path
    return out


def same_case(config, manifest, case):
    """The other run's result of `case`: its row of one of the case's studies whose values of the axes
    that study varies are the case's; None if it has none."""
    for study in case.studies:
        axes = [a for a in config["studies"][study].get("vary", {}) if a in manifest]
        rows = manifest[manifest["studies"].fillna("").str.split().apply(lambda names: study in names)]
        for axis in axes:
            rows = rows.loc[np.array([_same_value(v, case.values[axis]) for v in rows[axis]], dtype=bool)]
        if len(rows):
            return rows.iloc[0]["result"]
    return None


def _same_value(a, b):
    """A manifest's value (read back from CSV: numbers as floats) against a case's."""
    try:
        return bool(np.isclose(float(a), float(b), rtol=1e-9, atol=0))
    except (TypeError, ValueError):
        return str(a) == str(b)


def missing_note(config):
    """The page's word where the other run's claims are not there: which folder, and how to make it."""
    path = other_claims_file(config)
    if not path or os.path.exists(path):
        return ""
    _, other_label, _ = other(config)
    return (f"<div class='warning'><b>The {html.escape(other_label)} has not been run</b> (no <code>"
            f"{html.escape(path)}</code>): run <code>snakemake --cores 2</code> and then this target again to "
            f"see every claim under both configurations side by side; its column and its dashed curves are "
            f"left out until then.</div>")


def side_by_side(rows, other_rows):
    """One row per claim of this run (rows: claims.evaluate) with the other run's value and verdict for the
    same claim (matched by its text and figure), and whether the verdict changed."""
    theirs = {(r["claim"], str(r["figure"])): r for r in other_rows}
    out = []
    for r in rows:
        o = theirs.get((r["claim"], str(r["figure"])), {})
        other_verdict = o.get("verdict", "not run")
        out.append({"claim": r["claim"], "figure": r["figure"], "measured": r["measured"],
                    "threshold": r["threshold"], "other_value": o.get("value", np.nan),
                    "other_verdict": other_verdict, "value": r["value"], "verdict": r["verdict"],
                    "changed": judged(other_verdict) and judged(r["verdict"]) and other_verdict != r["verdict"]})
    return out


def judged(verdict):
    return verdict in ("agree", "disagree")


def read_other_claims(path):
    """The other run's claims table as rows, or None if that run has not been made."""
    if not path or not os.path.exists(path):
        return None
    return pd.read_csv(path, keep_default_na=True).to_dict("records")


def section(config, rows):
    """The report's claims section for a run with `compare_with`: the two runs side by side and, in plain
    words, which conclusions changed; or a note saying how to get the other run."""
    out_dir, other_label, this_label = other(config)
    other_rows = read_other_claims(other_claims_file(config))
    if other_rows is None:
        return missing_note(config)
    table = side_by_side(rows, other_rows)
    head = ("<table><tr><th>paper's claim</th><th>fig</th><th>measured</th><th>agree if</th>"
            f"<th>{html.escape(other_label)}: value</th><th>verdict</th>"
            f"<th>{html.escape(this_label)}: value</th><th>verdict</th><th>changed</th></tr>")
    body = "".join(
        f"<tr><td>{html.escape(r['claim'])}</td><td>{r['figure']}</td><td>{html.escape(r['measured'])}</td>"
        f"<td>{html.escape(r['threshold'])}</td><td>{cell_text(r['other_value'])}</td>"
        f"<td class='verdict'>{r['other_verdict']}</td><td>{cell_text(r['value'])}</td>"
        f"<td class='verdict'><b>{r['verdict']}</b></td><td>{'yes' if r['changed'] else ''}</td></tr>"
        for r in table)
    return f"<p>Source of the other column: <code>{html.escape(out_dir)}</code>.</p>{head}{body}</table>" + \
        changed_text(table, other_label, this_label)


def changed_text(table, other_label, this_label):
    """Which conclusions changed between the runs, in plain words, with their values."""
    judged_both = [r for r in table if judged(r["verdict"]) and judged(r["other_verdict"])]
    changed = [r for r in judged_both if r["changed"]]
    head = (f"<h3>Which conclusions changed</h3><p>Of {len(table)} claims, {len(judged_both)} are judged in both "
            f"runs; {len(changed)} changed verdict.")
    if not changed:
        return head + " Every conclusion judged in both runs stands under both configurations.</p>"
    items = "".join(
        f"<li>{html.escape(r['claim'])} (fig {r['figure']}): {r['other_verdict']} with the "
        f"{html.escape(other_label)} ({html.escape(r['measured'])} = {cell_text(r['other_value'])}), "
        f"{r['verdict']} with the {html.escape(this_label)} ({cell_text(r['value'])}; agree if "
        f"{html.escape(r['threshold'])}).</li>" for r in changed)
    return head + f"</p><ul>{items}</ul>"
