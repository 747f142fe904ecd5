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


@pytest.fixture(scope="session")
def small_runs(cellsim, tmp_path_factory):
    """{dryness: (result, dried state)} of a small cell (the regression cells' settings), fresh and
    X/X0 = 0.5 dried to steady state, compressed briefly, with snapshots in both stages: ~10 s, real
    files for the figures and the 3-D pages."""
    d = tmp_path_factory.mktemp("small runs")  # a space in the path, as users' paths may have
    case = d / "case.json"
    case.write_text('{"cell": {"n_wall": 642, "n_fluid": 700, "turgor_kPa": 100}, "coupling": {"repulsion_f0_N_m": 1.5e-11},'
                    ' "drying": {"steps": 120000, "ramp_time_us": 16, "steady_rms_speed_m_s": 0.05},'
                    ' "compression": {"steps": 1500, "plate_speed_m_s": 5}, "output": {"snapshot_every": 1000}}')
    runs = {}
    for dryness in (1.0, 0.5):
        dried, result = d / f"dried X{dryness}.h5", d / f"run X{dryness}.h5"
        for args in (["-o", str(dried), "--set", "compression.steps=0"], ["--from", str(dried), "-o", str(result)]):
            subprocess.run([cellsim, "run", str(case), "--quiet", "--set", f"drying.dryness={dryness}", *args],
                           check=True, capture_output=True)
        runs[dryness] = (str(result), str(dried))
    return runs


def run_ci_workflow(root, out, *extra, timeout=1800):
    """snakemake on config/ci.yaml into `out` (its own output folder, so runs do not collide)."""
    return subprocess.run(["snakemake", "--nolock", "--cores", "2", "--configfile", "config/ci.yaml",
                           "--config", f"output_dir={out}", "-q", *extra], cwd=root, capture_output=True,
                          text=True, timeout=timeout)


def run_reduced_target(root, out, target, reduced_config, timeout=1800):
    """snakemake `target` on config/ci.yaml and a reduced config (tests/*_reduced.yaml) into `out`;
    asserts that it succeeds and returns `out`."""
    done = subprocess.run(["snakemake", "--nolock", "--cores", "2", target, "--configfile", "config/ci.yaml",
                           reduced_config, "--config", f"output_dir={out}", "-q"], cwd=root,
                          capture_output=True, text=True, timeout=timeout)
    assert done.returncode == 0, (done.stdout + done.stderr)[-4000:]
    return out


@pytest.fixture(scope="session")
def ci_run(root, tmp_path_factory):
    """The whole workflow on config/ci.yaml, uninterrupted; shared by the tests that need it."""
    out = tmp_path_factory.mktemp("ci-results")
    done = run_ci_workflow(root, out)
    assert done.returncode == 0, (done.stdout + done.stderr)[-4000:]
    return out
