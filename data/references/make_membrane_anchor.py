"""The membrane anchor's curve (docs/model.md §9): the plate stress of the paper's cell without its
contraction springs (k_wc = 0), a closed membrane bag of the fluid, pressed between plates, as
analysis/anchors.py solves it (axisymmetric, bending left out). Not data: the analytic reference the
convergence target's membrane runs are drawn against (figure conv06).

The cell: R0 = 75 um, G t0 = 18 MPa x 6 um, P_T = 200 kPa, K = 20 MPa, gamma = 7, plates of 150 x
150 um (plate stress = force / their area); the membrane modulus M = 2 c G t0 with the mesh factor
c = sum(l0^2) / (2 sqrt 3 A0) of level 3's wall (8268 particles), the finest the target runs.

Run: /usr/bin/python3 data/references/make_membrane_anchor.py (rewrites membrane_anchor.csv; a slow
test recomputes its first rows).
"""
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1]))
from analysis import anchors  # noqa: E402

LEVEL3_MESH_FACTOR = 1.0736  # anchors.network_factor of the level-3 mesh (2026-11-26)
CELL = dict(radius_m=75e-6, modulus_N_m=2 * LEVEL3_MESH_FACTOR * 18e6 * 6e-6, turgor_Pa=2e5, bulk_modulus_Pa=20e6,
            eos_exponent=7)
PLATE_AREA_M2 = 150e-6 * 150e-6


def curve(largest_strain=0.2):
    """(strain, plate stress in Pa) of the membrane solution, from the first contact on."""
    solution = anchors.membrane_between_plates(**CELL, largest_strain=largest_strain)
    return solution["strain"], solution["force_N"] / PLATE_AREA_M2


def write(path=HERE / "membrane_anchor.csv"):
    strain, stress = curve()
    lines = ["# strain [1], plate stress [Pa]; the axisymmetric membrane solution, see make_membrane_anchor.py"]
    lines += [f"{e:.6f},{s:.3f}" for e, s in zip(strain, stress)]
    path.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    write()
