"""Shared fixtures: where the built solver is, and the repository root."""
import os
import pathlib
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
