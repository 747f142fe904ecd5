"""Which code made a page: the project's version (CMakeLists.txt's `project(... VERSION x.y.z)`, the one
place it is set; CITATION.cff and CHANGELOG.md repeat it, and tests/test_docs.py checks that they agree)
and the git commit of the checkout, marked when the checkout had changes not yet committed."""
import json
import pathlib
import re
import subprocess

ROOT = pathlib.Path(__file__).resolve().parents[1]


def version(root=ROOT):
    match = re.search(r"project\(cellsim VERSION (\d+\.\d+\.\d+)", (pathlib.Path(root) / "CMakeLists.txt").read_text())
    return match.group(1) if match else "unknown"


def commit(root=ROOT):
    """The checkout's commit (12 hex digits), '+ changes' if files differ from it; 'unknown' outside git."""
    def git(*args):
        try:
            done = subprocess.run(["git", "-C", str(root), *args], capture_output=True, text=True)
        except OSError:  # no git on this machine
            return None
        return done.stdout.strip() if done.returncode == 0 else None
    head = git("rev-parse", "--short=12", "HEAD")
    if not head:
        return "unknown (not a git checkout)"
    changed = git("status", "--porcelain", "--untracked-files=no")
    return head + (" + changes not committed" if changed else "")


def line(root=ROOT):
    """'cellsim 0.2.0, commit 0123456789ab': what the header of every page of the report names."""
    return f"cellsim {version(root)}, commit {commit(root)}"


def record(root=ROOT):
    return {"version": version(root), "commit": commit(root)}


def write(path, root=ROOT):
    """The version and commit that made a results folder's tables (read by a run that compares with it)."""
    pathlib.Path(path).write_text(json.dumps(record(root), indent=2) + "\n")


def read(path):
    """A results folder's recorded version and commit, or None where it has none (made before 0.3.0)."""
    path = pathlib.Path(path)
    return json.loads(path.read_text()) if path.exists() else None
