"""ParaView opens our results for real: its own Python (pvbatch, under a virtual display) loads both
XDMF sidecars of a run, reads as many points, triangles and time steps as the HDF5 file holds, and
renders a picture that is not blank. scripts/setup installs ParaView, so CI runs this."""
import json
import pathlib
import shutil
import subprocess

import h5py
import matplotlib.image
import numpy as np
import pytest

HERE = pathlib.Path(__file__).parent


@pytest.mark.skipif(shutil.which("pvbatch") is None or shutil.which("xvfb-run") is None,
                    reason="ParaView (pvbatch) or xvfb-run is not installed: scripts/setup installs "
                           "paraview, python3-paraview, xvfb and xauth")
def test_paraview_reads_and_renders_both_sidecars(cellsim, tmp_path):
    case = tmp_path / "case.json"
    case.write_text('{"cell": {"n_wall": 642, "n_fluid": 500}, "coupling": {"repulsion_f0_N_m": 1.5e-11},'
                    ' "drying": {"steps": 300}, "compression": {"steps": 300, "plate_speed_m_s": 5},'
                    ' "output": {"snapshot_every": 100}}')
    subprocess.run([cellsim, "run", str(case), "-o", str(tmp_path / "run.h5"), "--quiet"], check=True,
                   capture_output=True)
    png = tmp_path / "paraview.png"
    # -noreset: without it the virtual X server resets when its last client disconnects, and pvbatch,
    # which opens the display more than once, meets a server mid-reset on a busy machine ("bad X
    # server connection", SIGABRT; CI hit it, and 9 of 20 runs here with both cores loaded; 0 of 40
    # with -noreset). A 24-bit screen, as OpenGL wants.
    command = ["xvfb-run", "-a", "-s", "-noreset -screen 0 1280x1024x24",
               "pvbatch", str(HERE / "paraview_check.py"), str(tmp_path / "run"), str(png)]
    done = subprocess.run(command, capture_output=True, text=True, timeout=300)
    errors = [line for line in (done.stdout + done.stderr).splitlines() if "ERR|" in line]
    assert done.returncode == 0, "\n".join(errors) + (done.stdout + done.stderr)[-2000:]
    line = next(line for line in done.stdout.splitlines() if line.startswith("PARAVIEW_READ "))
    read = json.loads(line.split(" ", 1)[1])
    with h5py.File(tmp_path / "run.h5") as f:
        n_snapshots = len(f["snapshots"])
        n_wall, n_triangles = f["state/wall_positions"].shape[0], f["mesh/triangles"].shape[0]
        n_fluid = f["state/fluid_positions"].shape[0]
    assert n_snapshots >= 7  # drying and compression
    assert read["wall"] == {**read["wall"], "points": n_wall, "cells": n_triangles, "times": n_snapshots}
    assert read["fluid"]["points"] == n_fluid and read["fluid"]["times"] == n_snapshots
    assert "pressure" in read["fluid"]["arrays"] and "velocities" in read["wall"]["arrays"]
    image = matplotlib.image.imread(png)
    assert image.shape[:2] == (600, 800)
    assert np.std(image[..., :3]) > 0.02, "the rendered picture is blank"
