"""The cell in 3-D in the browser (analysis/cell_view.py, paper/cell_view.html): headless Chromium opens
the page of a fresh and a dried case from disk, with three.js copied from Debian's libjs-three, at the
first and the last slider position. Each must render (the page reports it and no JavaScript error),
draw something (the picture is not blank), and the two positions must differ. Set
CELLSIM_KEEP_SCREENSHOTS=DIR to keep the pictures."""
import os
import re
import pathlib
import shutil
import subprocess

import matplotlib.image
import numpy as np
import pytest

from analysis import cell_view

THREE = pathlib.Path("/usr/share/javascript/three")
CHROMIUM = shutil.which("chromium")
pytestmark = pytest.mark.skipif(CHROMIUM is None or not (THREE / "three.min.js").exists(),
                                reason="chromium or libjs-three is not installed: scripts/setup installs both")


def browse(page, fragment, out, *extra):
    return subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--enable-unsafe-swiftshader", "--window-size=900,700",
                           "--virtual-time-budget=8000", *extra, f"{page.as_uri()}#{fragment}"],
                          capture_output=True, text=True, timeout=120, cwd=out)


def test_pages_render_each_snapshot_offline(small_runs, tmp_path):
    report = tmp_path / "report"
    (report / "cells").mkdir(parents=True)
    (report / "js").mkdir()
    shutil.copy(THREE / "three.min.js", report / "js")
    shutil.copy(THREE / "examples" / "js" / "controls" / "OrbitControls.js", report / "js")
    keep = os.environ.get("CELLSIM_KEEP_SCREENSHOTS")
    for dryness, (result, dried) in small_runs.items():
        name = f"small_X{dryness}"
        page, data = report / "cells" / f"{name}.html", report / "cells" / f"{name}.data.js"
        cell_view.write(name, result, dried, page, data)
        text = data.read_text()
        assert "http" not in page.read_text().split("<script>")[0], "the page must not fetch anything"
        n_frames = text.count('"time_us"')
        assert n_frames >= 4 and '"stage": "drying"' in text and '"stage": "compression"' in text
        pictures = []
        for k, fragment in ((0, "snapshot=0"), (n_frames - 1, f"snapshot={n_frames - 1}&colour=wall_strain")):
            dom = browse(page, fragment, tmp_path, "--dump-dom").stdout
            status = re.search(r'<div id="status">([^<]*)</div>', dom)
            assert status, dom[-2000:]
            assert status.group(1) == f"rendered snapshot {k + 1} of {n_frames}", status.group(1)  # no JS error
            png = tmp_path / f"{name}-{k}.png"
            done = browse(page, fragment, tmp_path, f"--screenshot={png}")
            assert png.exists(), done.stderr[-2000:]
            image = matplotlib.image.imread(png)[200:, :, :3]  # below the controls: the canvas alone
            assert image.std() > 0.05, f"{name} snapshot {k}: the canvas is blank"
            pictures.append(image)
            if keep:
                shutil.copy(png, keep)
        assert np.abs(pictures[0] - pictures[1]).mean() > 0.01, f"{name}: the two slider positions look the same"


def test_a_tissue_page_colours_each_cell(cellsim, tmp_path):
    """Two small cells side by side (model.md §10): the page opens coloured by cell, in two colours."""
    case = tmp_path / "tissue.json"
    case.write_text('{"cell": {"n_wall": 162, "n_fluid": 120, "diameter_um": 40}, "time": {"dt_ns": 0.5},'
                    ' "tissue": {"cells_x": 2, "wall_gap_um": 1.6}, "settle": {"max_iterations": 200},'
                    ' "drying": {"steps": 400}, "compression": {"steps": 400, "plate_length_um": 120,'
                    ' "plate_width_um": 120, "gap_um": 0.2}, "output": {"snapshot_every": 200}}')
    result = tmp_path / "tissue.h5"
    subprocess.run([cellsim, "run", str(case), "-o", str(result), "--quiet"], check=True, capture_output=True)
    report = tmp_path / "report"
    (report / "cells").mkdir(parents=True)
    (report / "js").mkdir()
    shutil.copy(THREE / "three.min.js", report / "js")
    shutil.copy(THREE / "examples" / "js" / "controls" / "OrbitControls.js", report / "js")
    page, data = report / "cells" / "tissue.html", report / "cells" / "tissue.data.js"
    cell_view.write("tissue", result, result, page, data)
    assert '"n_cells": 2' in data.read_text()
    dom = browse(page, "snapshot=0", tmp_path, "--dump-dom").stdout
    assert re.search(r'<div id="status">rendered snapshot 1 of \d+</div>', dom), dom[-2000:]
    assert "each cell its own colour" in dom
    png = tmp_path / "tissue.png"
    browse(page, "snapshot=0", tmp_path, f"--screenshot={png}")
    image = matplotlib.image.imread(png)[200:, :, :3]
    # The first two cell colours (blue 0.12, 0.47, 0.71 and orange 1.0, 0.5, 0.05), lit and half
    # transparent over white: blue-dominant and red-dominant pixels both appear.
    blue = (image[..., 2] > image[..., 0] + 0.15).mean()
    orange = (image[..., 0] > image[..., 2] + 0.25).mean()
    assert blue > 0.002 and orange > 0.002, (blue, orange)
