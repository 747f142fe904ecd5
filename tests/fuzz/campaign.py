"""The fuzzing campaign (issue 51): scripts/fuzz KIND --seed S --count N. Every mutant's outcome is
judged by the rules (rules.py); the counts by exit code and every broken rule are printed, and the
mutants that broke one are written to DIR/defects.jsonl, with their seed and operations, to replay.
--sample K keeps K mutants (spread over the exits) in DIR/sample.jsonl: the corpus is made from them."""
import argparse
import collections
import json
import random
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tests.fuzz import case_mutations, config_mutations, file_corruptions, solver_cases  # noqa: E402


def schema_keys(cellsim):
    table = subprocess.run([cellsim, "params"], capture_output=True, text=True, check=True).stdout
    return [line.split("`")[1] for line in table.splitlines() if line.startswith("| `")]


def cases(args, scratch):
    mutator = case_mutations.CaseMutator(random.Random(args.seed), schema_keys(args.cellsim))
    mutants = [mutator.mutant() for _ in range(args.count)]

    def one(i):
        folder = scratch / f"m{i}"
        rc_v, rc_r, broken = solver_cases.check_mutant(args.cellsim, mutants[i], folder)
        shutil.rmtree(folder, ignore_errors=True)
        return i, f"validate {rc_v} / run {rc_r}", broken

    return mutants, one


def configs(args, scratch):
    mutator = config_mutations.ConfigMutator(random.Random(args.seed), ROOT)
    mutants = [mutator.mutant() for _ in range(args.count)]

    def one(i):
        rc, broken = config_mutations.check_mutant(ROOT, mutants[i], scratch / f"c{i}")
        return i, f"snakemake -n {rc}", broken

    return mutants, one


def files(args, scratch):
    corrupter = file_corruptions.Corrupter(random.Random(args.seed), args.cellsim, scratch / "sources")
    mutants = [corrupter.mutant() for _ in range(args.count)]

    def one(i):
        folder = scratch / f"f{i}"
        rc, broken = corrupter.check(mutants[i], folder)
        shutil.rmtree(folder, ignore_errors=True)
        return i, f"--from {rc}", broken

    return mutants, one


KINDS = {"cases": cases, "configs": configs, "files": files}


def main(argv=None):
    parser = argparse.ArgumentParser(prog="scripts/fuzz", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("kind", choices=sorted(KINDS))
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--count", type=int, default=100)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--cellsim", default=str(ROOT / "build-sanitize" / "solver" / "cellsim"),
                        help="the solver to fuzz (default: the sanitizer build scripts/test makes)")
    parser.add_argument("--keep", type=Path, default=Path("fuzz-results"), help="where defects.jsonl goes")
    parser.add_argument("--sample", type=int, default=0, help="keep this many mutants in DIR/sample.jsonl")
    args = parser.parse_args(argv)
    if args.count < 1 or args.jobs < 1:
        parser.error("--count and --jobs must be positive")
    if args.kind != "configs" and not Path(args.cellsim).is_file():
        parser.error(f"no solver at {args.cellsim}: build it (scripts/test does) or give --cellsim")
    args.keep.mkdir(parents=True, exist_ok=True)
    t0 = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="cellsim-fuzz-") as tmp:
        mutants, one = KINDS[args.kind](args, Path(tmp))
        exits, defects, outcome_of = collections.Counter(), [], {}
        with ThreadPoolExecutor(args.jobs) as pool:
            for done, (i, outcome, broken) in enumerate(pool.map(one, range(len(mutants))), 1):
                exits[outcome] += 1
                outcome_of[i] = outcome
                if broken:
                    defects.append({**mutants[i].as_record(), "outcome": outcome, "broken": broken})
                    print(f"DEFECT #{i} ({outcome}): {mutants[i].ops}: {broken}", flush=True)
                if done % 100 == 0 or done == len(mutants):
                    print(f"{args.kind}: {done}/{len(mutants)} in {time.monotonic() - t0:.0f} s, "
                          f"{len(defects)} broke a rule", file=sys.stderr, flush=True)
    with open(args.keep / "defects.jsonl", "w") as f:
        for d in defects:
            f.write(json.dumps(d) + "\n")
    if args.sample:
        by_outcome = collections.defaultdict(list)
        for i, outcome in sorted(outcome_of.items()):
            by_outcome[outcome].append(i)
        picked, rng = [], random.Random(args.seed)
        while len(picked) < min(args.sample, len(mutants)):
            for outcome in sorted(by_outcome):
                if by_outcome[outcome] and len(picked) < args.sample:
                    picked.append(by_outcome[outcome].pop(rng.randrange(len(by_outcome[outcome]))))
        with open(args.keep / "sample.jsonl", "w") as f:
            for i in sorted(picked):
                f.write(json.dumps({**mutants[i].as_record(), "outcome": outcome_of[i]}) + "\n")
    print(f"\n{args.kind}: {len(mutants)} mutants, seed {args.seed}, {time.monotonic() - t0:.0f} s")
    for outcome, n in sorted(exits.items()):
        print(f"  {outcome:28s} {n}")
    print(f"  broke a rule                 {len(defects)} (in {args.keep / 'defects.jsonl'})")
    return 1 if defects else 0


if __name__ == "__main__":
    sys.exit(main())
