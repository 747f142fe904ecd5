"""Reading a run's results yourself: the summary table with pandas, one case's HDF5 file with h5py, and
its stress-strain curve drawn with matplotlib. Every name used here is listed in docs/output-reference.md.

    python3 docs/examples/read_results.py results/                  # the first case of the summary
    python3 docs/examples/read_results.py results/ D150_G18_P200_t6_v1_X0.5 -o curve.png

It prints the case's row of the summary and the file's state, and writes the curve (curve.png by default).
"""
import argparse
import sys
from pathlib import Path

import h5py
import matplotlib

matplotlib.use("Agg")  # no display needed: the curve is written to a file
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402


def read_curve(h5_path):
    """The compression's nominal strain and plate stress [kPa] of one result file, and its root attributes."""
    with h5py.File(h5_path, "r") as f:
        attributes = {key: f.attrs[key] for key in ("completed", "warning", "solver_version")}
        series = pd.DataFrame({name: f["timeseries"][name][:] for name in
                               ("time_s", "stage", "nominal_strain", "plate_stress_Pa")})
    compression = series[series["stage"] == 1]  # stage 0 is the drying, 1 the compression
    return compression["nominal_strain"], compression["plate_stress_Pa"] / 1e3, attributes


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("results", type=Path, help="a results folder (results/, results-ci/, ...)")
    parser.add_argument("case", nargs="?", help="a case's name (default: the summary's first)")
    parser.add_argument("-o", "--output", type=Path, default=Path("curve.png"), help="where to draw the curve")
    args = parser.parse_args(argv)

    summary_path = args.results / "tables" / "summary.csv"
    if not summary_path.is_file():
        sys.exit(f"no {summary_path}: run the workflow into {args.results} first")
    summary = pd.read_csv(summary_path).set_index("case")
    case = args.case or summary.index[0]
    if case not in summary.index:
        sys.exit(f"no case {case!r} in {summary_path}; it has {', '.join(summary.index[:5])}, ...")
    row = summary.loc[case]
    print(f"{case}: dried to V/V0 = {row['dried_V_over_V0']:.3f}, "
          f"stress at strain 0.05 = {row['stress_kPa_at_0.05']:.1f} kPa (summary.csv)")

    strain, stress_kPa, attributes = read_curve(args.results / "runs" / f"{case}.h5")
    print(f"runs/{case}.h5: completed = {attributes['completed']}, solver {attributes['solver_version']}, "
          f"warning: {attributes['warning'] or 'none'}; {len(strain)} compression records")

    figure, ax = plt.subplots(figsize=(4.5, 3.5), layout="constrained")
    ax.plot(strain, stress_kPa, label=case)
    ax.set_xlabel("nominal strain (H_c - H)/H_c")
    ax.set_ylabel("plate stress [kPa]")
    ax.legend(fontsize=7)
    figure.savefig(args.output, dpi=100)
    print(f"drew {args.output}")


if __name__ == "__main__":
    main()
