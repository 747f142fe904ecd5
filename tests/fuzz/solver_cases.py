"""One case mutant through the solver: `cellsim validate` on it as written, then a tiny run (every
stage capped at a few dozen steps, every size at a small cell) of what validate accepted, or the run
of what it refused, which must refuse it alike. Returns the rules broken (rules.py)."""
import json
import os
import subprocess
import time
from pathlib import Path

import h5py

from tests.fuzz import rules

VALIDATE_LIMIT_S = 300  # a cell of a million particles takes a minute to build under the sanitizers
RUN_LIMIT_S = 180
# The tiny run's caps: a case that validate accepted runs at most this big and this long. A key left
# out takes the cap too where its default is larger (the stages' caps, the default cell's particles).
STEP_CAPS = {("settle", "max_iterations"): 60, ("drying", "steps"): 60, ("compression", "steps"): 60}
SIZE_CAPS = {("cell", "n_wall"): 642, ("cell", "n_fluid"): 700, ("tissue", "cells_x"): 2,
             ("tissue", "cells_y"): 2, ("tissue", "cells_z"): 2}
CAPPED_WHEN_ABSENT = set(STEP_CAPS) | {("cell", "n_wall"), ("cell", "n_fluid")}


def _number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def capped(text):
    """The case text with its stages and sizes capped (None if it is not a JSON object of sections)."""
    try:
        case = json.loads(text.removeprefix("\ufeff"))  # the solver reads a byte-order mark as JSON allows
    except (ValueError, RecursionError):
        return None
    if not isinstance(case, dict):
        return None
    for (s, k), cap in {**STEP_CAPS, **SIZE_CAPS}.items():
        body = case.get(s, {})
        if not isinstance(body, dict):
            continue
        value = body.get(k)
        absent = k not in body or (value is None and (s, k) in STEP_CAPS)  # a stage cap's null: derived
        if (absent and (s, k) in CAPPED_WHEN_ABSENT) or (_number(value) and value > cap):
            case.setdefault(s, body)[k] = cap
    return json.dumps(case)


# The sanitizers' settings of scripts/test's sanitizer tier, its LeakSanitizer suppressions too (a build
# without the sanitizers ignores them).
SANITIZER_ENV = {"ASAN_OPTIONS": "detect_leaks=1:abort_on_error=0", "UBSAN_OPTIONS": "halt_on_error=1:print_stacktrace=1",
                 "LSAN_OPTIONS": f"suppressions={Path(__file__).resolve().parents[2] / 'scripts' / 'lib' / 'lsan.supp'}"}


def execute(args, limit_s, out=None, whole_stacks=False):
    """One solver command under the sanitizers' settings, with a time limit: its Outcome. whole_stacks:
    unwind every allocation's stack in full (2-3 times slower), which the suppression of HDF5's own leak
    on a corrupted file needs (scripts/lib/lsan.supp)."""
    env = {**os.environ, **SANITIZER_ENV}
    if whole_stacks:
        env["ASAN_OPTIONS"] += ":fast_unwind_on_malloc=0"
    t0 = time.monotonic()
    try:
        done = subprocess.run(args, capture_output=True, timeout=limit_s, env=env)
        rc, err, text = done.returncode, done.stderr.decode("utf-8", "replace"), done.stdout.decode("utf-8", "replace")
    except subprocess.TimeoutExpired as e:
        rc, err, text = None, (e.stderr or b"").decode("utf-8", "replace"), ""
    return rules.Outcome(" ".join(map(str, args))[:300], rc, err, out, time.monotonic() - t0, text)


def result_attributes(path):
    with h5py.File(path, "r") as f:
        attrs = {k: f.attrs[k] for k in f.attrs}
        attrs = {k: (v.decode() if isinstance(v, bytes) else v.item() if hasattr(v, "item") else v)
                 for k, v in attrs.items()}
        f["timeseries/time_s"][()]  # the series opens and reads
        return attrs


def asks_for_an_end(text):
    try:
        comp = json.loads(text.removeprefix("\ufeff")).get("compression", {})
    except (ValueError, AttributeError, RecursionError):
        return False
    return isinstance(comp, dict) and any(comp.get(k) not in (None, 0) for k in ("end_strain", "unload_at_strain"))


def write_case(path, text):
    path.write_text(text, encoding="utf-8", errors="surrogateescape")


def check_mutant(cellsim, mutant, folder):
    """Runs one mutant in `folder` (emptied first); returns (validate rc, run rc or None, broken rules)."""
    folder.mkdir(parents=True, exist_ok=True)
    for old in folder.iterdir():
        old.unlink()
    case = folder / "case.json"
    write_case(case, mutant.text)
    sets = [a for o in mutant.overrides for a in ("--set", o)]
    v = execute([cellsim, "validate", case, *sets], VALIDATE_LIMIT_S)
    broken = [f"validate: {b}" for b in rules.judge_validate(v)]
    run_case = case
    if v.returncode == 0:
        tiny = capped(mutant.text)
        if tiny is None:
            return v.returncode, None, broken + ["validate accepted a file that is not a JSON object"]
        run_case = folder / "tiny.json"
        write_case(run_case, tiny)
        t = execute([cellsim, "validate", run_case, *sets], VALIDATE_LIMIT_S)
        if t.returncode != 0:
            return v.returncode, None, broken  # the caps made it invalid (e.g. a period too small): not run
        # The case validate prints, resolved (of the tiny case: small, so quick under the sanitizers),
        # must read back as itself.
        resolved = folder / "resolved.json"
        write_case(resolved, t.stdout)
        broken += [f"validate: {b}" for b in
                   rules.judge_round_trip(t, execute([cellsim, "validate", resolved], VALIDATE_LIMIT_S))]
    elif v.returncode != 2:
        return v.returncode, None, broken
    out = folder / "out.h5"
    r = execute([cellsim, "run", run_case, "-o", out, "--quiet", *sets], RUN_LIMIT_S, out=out)
    broken += [f"run: {b}" for b in rules.judge_run(r, result_attributes, asks_for_an_end(mutant.text))]
    broken += rules.judge_pair(v, r)
    return v.returncode, r.returncode, broken
