"""Compares two cellsim builds on this machine: runs `cellsim bench` of both at the same time, one
per core, swapping cores each round, and prints the median ms per step per phase and the ratios.
Shared virtual machines change speed within minutes; timing both side by side cancels that.

usage: scripts/bench-compare OLD_CELLSIM NEW_CELLSIM [ROUNDS] [CASE.json]"""
import re
import statistics
import subprocess
import sys


def parse(output):
    phases = {"total": float(re.search(r"median ([\d.]+) ms/step", output).group(1))}
    for line in output.splitlines():
        row = re.match(r"(.+?)\s{2,}([\d.]+)\s+[\d.]+%$", line)
        if row:
            phases[row.group(1).split(" (")[0]] = float(row.group(2))
    return phases


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    old, new = argv[1], argv[2]
    rounds = int(argv[3]) if len(argv) > 3 else 4
    case = argv[4] if len(argv) > 4 else "solver/examples/apple-baseline.json"
    runs = {old: [], new: []}
    for r in range(rounds):
        cores = (0, 1) if r % 2 == 0 else (1, 0)
        procs = [subprocess.Popen(["taskset", "-c", str(core), exe, "bench", case, "--steps", "1000", "--repeats", "3"],
                                  stdout=subprocess.PIPE, text=True) for exe, core in zip((old, new), cores)]
        for exe, proc in zip((old, new), procs):
            out, _ = proc.communicate()
            if proc.returncode:
                sys.exit(f"{exe} bench failed (exit {proc.returncode})")
            runs[exe].append(parse(out))
        print(f"round {r + 1}/{rounds} done", file=sys.stderr)
    print(f"{'phase (ms/step, median)':32s} {'old':>8s} {'new':>8s} {'new/old':>8s}")
    phases = list(runs[old][0]) + [p for p in runs[new][0] if p not in runs[old][0]]
    for phase in phases:
        if phase not in runs[old][0] or phase not in runs[new][0]:  # a phase only one build times
            only = old if phase in runs[old][0] else new
            value = f"{statistics.median(x[phase] for x in runs[only]):8.4f}"
            print(f"{phase:32s} {value if only == old else '-':>8s} {value if only == new else '-':>8s} {'-':>8s}")
            continue
        a = statistics.median(x[phase] for x in runs[old])
        b = statistics.median(x[phase] for x in runs[new])
        ratio = statistics.median(n[phase] / o[phase] if o[phase] else 1.0 for o, n in zip(runs[old], runs[new]))
        print(f"{phase:32s} {a:8.4f} {b:8.4f} {ratio:8.3f}")


if __name__ == "__main__":
    main(sys.argv)
