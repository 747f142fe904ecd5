"""Shared fixtures: where the built solver is, and the repository root."""
import os
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the analysis package


@pytest.fixture(scope="session")
def cellsim():
    """Path of the cellsim executable (scripts/test builds it and sets CELLSIM)."""
    exe = os.environ.get("CELLSIM") or str(ROOT / "build" / "solver" / "cellsim")
    if not (os.path.isfile(exe) and os.access(exe, os.X_OK)):
        pytest.fail(f"cellsim not built at {exe}: run scripts/test (or set CELLSIM)")
    return exe


@pytest.fixture(scope="session")
def root():
    return ROOT


def run_ci_workflow(root, out, *extra, timeout=1800):
    """snakemake on config/ci.yaml into `out` (its own output folder, so runs do not collide)."""
    return subprocess.run(["snakemake", "--nolock", "--cores", "2", "--configfile", "config/ci.yaml",
                           "--config", f"output_dir={out}", "-q", *extra], cwd=root, capture_output=True,
                          text=True, timeout=timeout)


@pytest.fixture(scope="session")
def ci_run(root, tmp_path_factory):
    """The whole workflow on config/ci.yaml, uninterrupted; shared by the tests that need it."""
    out = tmp_path_factory.mktemp("ci-results")
    done = run_ci_workflow(root, out)
    assert done.returncode == 0, (done.stdout + done.stderr)[-4000:]
    return out
