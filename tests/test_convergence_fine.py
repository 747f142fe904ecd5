"""Target convergence_fine (analysis/convergence_fine.py): its plan (the closed cell at four levels, the paper's
wall and the membrane, quasi-static in 0.2 um steps) and its tables, on two small closed cells."""
import numpy as np
import pytest

from analysis import convergence_fine, matrix
from solver_runs import run_cases


@pytest.fixture(scope="module")
def config(root):
    return matrix.workflow_config([], root)


def test_the_target_runs_both_cells_at_four_levels_quasi_statically(config):
    cases = matrix.expand(config)
    for study in (convergence_fine.WALL, convergence_fine.MEMBRANE):
        runs = convergence_fine.runs_of(cases, study)
        assert [level for _, level in runs] == [1, 2, 3, 4]
        walls = [cases[name].case["cell"]["n_wall"] for name, _ in runs]
        assert walls == [2067, 4134, 8268, 16536]  # each level doubles the wall's particles
        for name, _ in runs:
            case = cases[name].case
            assert (case["fluid"]["model"], case["time"]["scheme"], case["time"]["dt_ns"]) == ("cavity", "quasi_static", 200)
            assert case["compression"]["end_strain"] == 0.22
            assert case["wall"]["contraction_stiffness_N_m"] == (0 if study == convergence_fine.MEMBRANE else 10000)
    assert set(matrix.target_figures(config, "convergence_fine")) == {"convf01", "convf02"}


@pytest.fixture(scope="module")
def small_ladder(cellsim, root, tmp_path_factory):
    """Two small closed cells (162 and 642 wall particles) pressed quasi-statically to strain 0.22, with and
    without contraction springs: [(case, level, path)] for each."""
    out = tmp_path_factory.mktemp("fine")
    keys = {"fluid.model": "cavity", "time.scheme": "quasi_static", "time.dt_ns": 200, "compression.steps": 400,
            "compression.end_strain": 0.22, "output.record_every": 1, "output.snapshot_every": 0}
    cases = {f"{kind}_{level}": {**keys, "cell.n_wall": n_wall, "wall.contraction_stiffness_N_m": k_wc}
             for level, n_wall in ((1, 162), (2, 642)) for kind, k_wc in (("wall", 10000), ("membrane", 0))}
    paths = run_cases(cellsim, root / "solver" / "examples" / "apple-baseline.json", out, cases)
    return {kind: [(f"{kind}_{level}", level, paths[f"{kind}_{level}"]) for level in (1, 2)]
            for kind in ("wall", "membrane")}


@pytest.mark.slow  # four quasi-static runs, about 50 s
def test_the_ladder_gives_each_level_its_stresses_and_change(small_ladder):
    table = convergence_fine.ladder(small_ladder["wall"])
    assert list(table["level"]) == [1, 2] and list(table["n_wall"]) == [162, 642]
    for strain in convergence_fine.STRAINS:
        stress = table[f"stress_kPa_at_{strain:.2f}"].to_numpy()
        assert np.all(stress > 0), strain
        change = table[f"change_at_{strain:.2f}"].to_numpy()
        assert np.isnan(change[0]) and change[1] == pytest.approx(stress[1] / stress[0] - 1)
    assert np.all(np.diff(table.iloc[0][[f"stress_kPa_at_{s:.2f}" for s in convergence_fine.STRAINS]].to_numpy(float)) > 0)


@pytest.mark.slow
def test_the_membrane_is_set_beside_its_solution_at_each_strain(small_ladder):
    table = convergence_fine.membrane(small_ladder["membrane"])
    assert len(table) == 2 * (len(convergence_fine.STRAINS) + 1)  # each strain, and F / (P A_c)
    forces = table[table["quantity"].str.startswith("plate force")]
    assert np.all(forces["analytic"] > 0) and np.all(np.isfinite(forces["measured / analytic"]))
    # The membrane's force, though coarse, is the solution's in size (within a factor of 2 at 162 particles).
    assert forces["measured / analytic"].between(0.5, 2.0).all(), forces
