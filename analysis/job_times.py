"""How long a target's solver jobs took, read from their logs (<output_dir>/logs/{settle,dry,compress}/):
the core time of each kind of job, and the longest chain, which is what a cluster with a core for every
job waits for: one case's settle, drying and compression, one after the other.

    python3 -m analysis.job_times --configfile config/converged.yaml [--target converged_bounds]

A job's time is what cellsim reports, its settle's and its steps' wall times ("... s wall time"); Snakemake's
own work between jobs is not in it. Jobs whose logs are missing (not run yet) are counted as such."""
import argparse
import pathlib
import re

from analysis import matrix

WALL_TIME = re.compile(r"([0-9.]+) s wall time")
KINDS = ("settle", "dry", "compress")


def job_seconds(log):
    """The wall times a cellsim log reports (the settle's and the steps'), summed; None without a log."""
    path = pathlib.Path(log)
    if not path.exists():
        return None
    return sum(float(t) for t in WALL_TIME.findall(path.read_text()))


def times(config, target=matrix.DEFAULT_TARGET):
    """{kind: {job name: seconds or None}} for the target's settles, dryings and compressions."""
    every = matrix.expand(config)
    cases = [every[name] for name in matrix.target_cases(config, every, target)]
    logs = pathlib.Path(config["output_dir"]) / "logs"
    names = {"settle": {c.rest for c in cases}, "dry": {c.dried for c in cases}, "compress": {c.name for c in cases}}
    return {kind: {n: job_seconds(logs / kind / f"{n}.log") for n in sorted(names[kind])} for kind in KINDS}, cases


def longest_chain(config, target=matrix.DEFAULT_TARGET):
    """(seconds, case name, (settle, dry, compress) seconds) of the target's longest chain of finished jobs."""
    measured, cases = times(config, target)
    best = (0.0, None, None)
    for case in cases:
        parts = (measured["settle"][case.rest], measured["dry"][case.dried], measured["compress"][case.name])
        if None not in parts and sum(parts) > best[0]:
            best = (sum(parts), case.name, parts)
    return best


def report(config, target=matrix.DEFAULT_TARGET):
    """The lines the command prints."""
    measured, _ = times(config, target)
    lines = []
    total = 0.0
    for kind in KINDS:
        done = [s for s in measured[kind].values() if s is not None]
        total += sum(done)
        missing = len(measured[kind]) - len(done)
        lines.append(f"{kind}: {len(done)} jobs, {sum(done) / 60:.1f} core-min"
                     + (f" ({missing} without a log)" if missing else ""))
    lines.append(f"all: {total / 60:.1f} core-min, {total / 120:.1f} min on 2 cores if they never wait")
    seconds, name, parts = longest_chain(config, target)
    if name:
        lines.append(f"longest chain: {seconds / 60:.1f} min, {name} (settle {parts[0]:.0f} s, drying {parts[1]:.0f} s, "
                     f"compression {parts[2]:.0f} s): a cluster's time")
    return lines


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--configfile", action="append", default=[], help="as given to snakemake (repeatable)")
    parser.add_argument("--target", default=matrix.DEFAULT_TARGET, help="a target of the config (default: the default one)")
    args = parser.parse_args(argv)
    print("\n".join(report(matrix.workflow_config(args.configfile), args.target)))


if __name__ == "__main__":
    main()
