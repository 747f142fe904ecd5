"""The rules every outcome of a fuzzed input must meet (issue 51): a known exit code only (0, 2, 3, 4;
validate 0 or 2), no sanitizer report, no hang; exit 2 writes nothing; exit 3 leaves only OUT.partial;
exit 0 writes a file that opens as a completed result; every refusal names a key, a file or a step;
the case validate prints reads back as itself. Each function returns the list of rules an outcome broke
(empty: it met them all)."""
import json
import re
from dataclasses import dataclass
from pathlib import Path

SANITIZER_MARKERS = ("Sanitizer", "runtime error:", "Segmentation", "core dumped", "terminate called",
                     "internal error")
# What a refusal must name: a section.key, an option, a file (quoted), or the step of a failure.
_NAMES = re.compile(r"\b[a-z_]+\.[A-Za-z0-9_]+|^cellsim: error: [a-z_]+ = |--set|--from|-o |'[^']+'|\bstep \d+")


@dataclass
class Outcome:
    """One solver command: its exit code (None if it outlived its time limit), its stderr, and the
    output path it was given (None for validate)."""
    command: str
    returncode: int | None
    stderr: str
    out: Path | None = None
    seconds: float = 0.0
    stdout: str = ""


def _message(stderr):
    lines = [line for line in stderr.splitlines() if line.startswith("cellsim: ")]
    return lines[-1] if lines else stderr.strip()[-300:]


def common(o, allowed):
    broken = []
    if o.returncode is None:
        return [f"hang: no exit within {o.seconds:.0f} s"]
    if o.returncode < 0:
        broken.append(f"killed by signal {-o.returncode}")
    elif o.returncode not in allowed:
        broken.append(f"exit {o.returncode} (allowed: {sorted(allowed)})")
    for marker in SANITIZER_MARKERS:
        if marker in o.stderr:
            broken.append(f"stderr says {marker!r}")
    if o.returncode in (2, 3, 4) and not _NAMES.search(_message(o.stderr)):
        broken.append(f"refusal names no key, file or step: {_message(o.stderr)[:200]!r}")
    return broken


def judge_validate(o):
    return common(o, {0, 2})


def judge_run(o, open_result, capped_before_end=False):
    """open_result(path) -> the file's attributes (raises if it does not open); capped_before_end: the
    case asked for an end (end_strain, or the unload's return) that its compression may not reach, so a
    completed file must either have reached it or say in its warning that it did not."""
    broken = common(o, {0, 2, 3, 4})
    out, partial = o.out, Path(str(o.out) + ".partial")
    rc = o.returncode
    if rc == 2 and (out.exists() or partial.exists()):
        broken.append("exit 2 left a file behind")
    if rc == 3:
        if out.exists():
            broken.append("exit 3 wrote the final name")
        if not partial.exists():
            broken.append("exit 3 left no .partial")
        if "step " not in _message(o.stderr):
            broken.append("numerical failure names no step")
    if rc == 4 and out.exists():
        broken.append("exit 4 wrote the final name")
    if rc == 0:
        if partial.exists():
            broken.append("exit 0 left a .partial")
        if not out.exists():
            broken.append("exit 0 wrote no file")
        else:
            try:
                attrs = open_result(out)
            except Exception as error:  # noqa: BLE001 - any failure to open is the defect
                return broken + [f"exit 0 wrote a file that does not open: {error}"]
            if attrs.get("completed") != 1:
                broken.append("exit 0 wrote a file not marked completed")
            if capped_before_end and not attrs.get("compression_reached_end", 1) and not attrs.get("warning"):
                broken.append("the compression stopped at its cap before its end, and the file does not say so")
    return broken


def _same_case(a, b, rel=1e-12):
    """Two resolved cases alike: the same keys and texts, numbers within rel (validate prints 15 digits,
    so a value derived from a printed one may move in its last)."""
    if isinstance(a, dict):
        return isinstance(b, dict) and a.keys() == b.keys() and all(_same_case(a[k], b[k], rel) for k in a)
    numbers = [isinstance(x, (int, float)) and not isinstance(x, bool) for x in (a, b)]
    if all(numbers):
        return abs(a - b) <= rel * max(abs(a), abs(b))
    return a == b


def judge_round_trip(first, again):
    """The case `validate` printed (first), validated again (again): accepted, the same case, and no
    warning the first did not give."""
    if again.returncode != 0:
        return [f"validate refused the case it printed: {_message(again.stderr)[:200]!r}"]
    try:
        same = _same_case(json.loads(first.stdout), json.loads(again.stdout))
    except ValueError:
        return ["validate printed a case that is not JSON"]
    warned = {line for line in first.stderr.splitlines() if "WARNING" in line}
    broken = [] if same else ["the case validate printed reads back as another case"]
    broken += [f"the case validate printed warns anew: {line[:200]!r}" for line in again.stderr.splitlines()
               if "WARNING" in line and line not in warned]
    return broken


def judge_pair(validate, run):
    """validate and run must agree on whether a case is valid."""
    if validate.returncode == 0 and run.returncode == 2:
        return [f"validate accepted what run refused: {_message(run.stderr)[:200]!r}"]
    if validate.returncode == 2 and run.returncode not in (2, None):
        return [f"validate refused ({_message(validate.stderr)[:120]!r}) what run took (exit {run.returncode})"]
    return []
