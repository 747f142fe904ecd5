"""The closed cell's ladder to level 4 (target convergence_fine): the paper's wall's stress at strains 0.05-0.20
at levels 1-4 with each level's change, and the membrane anchor's plate force (k_wc = 0) against the
axisymmetric solution for each run's mesh (analysis/anchors.py). Findings 6 and the limitations quote both."""
import pandas as pd

from analysis import aggregate, anchors, results

STRAINS = (0.05, 0.10, 0.15, 0.20)
WALL, MEMBRANE = "closed_cell_fine", "membrane_fine"


def runs_of(cases, study):
    """[(case name, level)] of one of the target's studies, by level."""
    runs = [(name, case.values.get("wall_level", 1)) for name, case in cases.items() if study in case.studies]
    return sorted(runs, key=lambda run: run[1])


def ladder(runs):
    """runs: [(case, level, path)] -> one row a level: the stress at each strain (interpolated between records,
    as the hand runs' table was) and its change from the level below."""
    rows = []
    for case, level, path in runs:
        ts = results.timeseries(path)
        row = {"case": case, "level": level, "n_wall": results.resolved_case(path)["cell"]["n_wall"]}
        for strain in STRAINS:
            row[f"stress_kPa_at_{strain:.2f}"] = aggregate.value_at_strain(ts, strain) / 1e3
        rows.append(row)
    table = pd.DataFrame(rows)
    for strain in STRAINS:
        column = f"stress_kPa_at_{strain:.2f}"
        table[f"change_at_{strain:.2f}"] = table[column] / table[column].shift() - 1
    return table


def membrane(runs):
    """runs: [(case, level, path)] -> the anchor's rows: plate force / the solution at each strain."""
    return pd.DataFrame([row for case, level, path in runs for row in anchors.membrane_rows(case, level, path, STRAINS)])
