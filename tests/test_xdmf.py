"""The XDMF sidecars open the snapshots: meshio reads mesh, time and fields from them."""
import subprocess

import h5py
import meshio
import numpy as np


def test_sidecars_read_with_meshio(cellsim, tmp_path):
    out = tmp_path / "run.h5"
    (tmp_path / "case.json").write_text('{"cell": {"n_wall": 642, "n_fluid": 500}, '
                                        '"coupling": {"repulsion_f0_N_m": 1.5e-11}, '  # coarse cells: config/ci.yaml
                                        '"drying": {"steps": 0}, "compression": {"steps": 0}}')
    subprocess.run([cellsim, "run", str(tmp_path / "case.json"), "-o", str(out)], check=True)

    with h5py.File(out) as f:
        wall_x = f["snapshots/000000000/wall_positions"][()]
        triangles = f["mesh/triangles"][()]
        fluid_x = f["snapshots/000000000/fluid_positions"][()]
    with meshio.xdmf.TimeSeriesReader(str(tmp_path / "run.wall.xdmf")) as reader:
        points, cells = reader.read_points_cells()
        t, point_data, _ = reader.read_data(0)
    assert t == 0.0
    np.testing.assert_array_equal(points, wall_x)
    assert cells[0].type == "triangle"
    np.testing.assert_array_equal(cells[0].data, triangles)
    assert point_data["velocities"].shape == (642, 3)

    with meshio.xdmf.TimeSeriesReader(str(tmp_path / "run.fluid.xdmf")) as reader:
        points, cells = reader.read_points_cells()
        _, point_data, _ = reader.read_data(0)
    np.testing.assert_array_equal(points, fluid_x)
    assert cells[0].type == "vertex" and len(cells[0].data) == 500
    assert np.all(point_data["density"] == 1000.0)
