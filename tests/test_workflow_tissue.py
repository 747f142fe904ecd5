"""The tissue target end to end on reduced cells (tests/tissue_reduced.yaml): its runs (one thread
each), its table and page (the clusters in the paper's numerics; the periodic slab, a cluster and the cell in
the pressure coupling's), its ten figures, the 3-D pages with each cell coloured, and none of the
default target's. Slow: about ten minutes on 2 cores."""
import pandas as pd
import pytest

from conftest import check_target_page, reduced_target_fixture

pytestmark = pytest.mark.slow
REDUCED = "tests/tissue_reduced.yaml"
tissue_run = reduced_target_fixture("tissue", REDUCED)


def test_tissue_table_compares_each_tissue_with_the_single_cell(tissue_run):
    everything = pd.read_csv(tissue_run / "tables" / "tissue" / "tissue.csv")
    table = everything[everything["numerics"] == "paper's (LJ)"]
    assert sorted(zip(table["cells"], table["X/X0"])) == [(1, 0.5), (1, 1.0), (8, 0.5), (8, 1.0)]
    tissues = table[table["cells"] == 8]
    assert tissues["porosity (dried)"].between(0.05, 0.6).all()
    # Fresh: the cells stay bonded while drying (nothing to pull them apart), and all of it is counted.
    fresh = tissues[tissues["X/X0"] == 1.0].iloc[0]
    assert fresh["bonds"] > 500 and fresh["broken in drying"] == 0
    assert fresh["broken between layers"] + fresh["broken on lateral faces"] == fresh["broken in compression"]
    assert (tissues["stress at 0.05 [kPa]"] > 0).all() and tissues["x single cell at 0.05"].notna().all()


def test_the_slab_beside_the_cluster_and_the_cell_in_one_numerics(tissue_run):
    table = pd.read_csv(tissue_run / "tables" / "tissue" / "tissue.csv")
    ours = table[table["numerics"] != "paper's (LJ)"]
    assert sorted(zip(ours["cells"], ours["sides"], ours["plate [m/s]"], ours["compression L_p"])) == [
        (1, "free", 1, 1e-12), (1, "free", 1, 1e-6), (8, "free", 1, 1e-12), (16, "confined", 1, 1e-12),
        (16, "confined", 4, 1e-12), (16, "unconfined", 1, 1e-12)]
    slabs = ours[ours["cells"] == 16]
    # Fresh, built from a lattice: nothing breaks in drying, the period's footprint holds the cells.
    assert (slabs["broken in drying"] == 0).all() and slabs["porosity (dried)"].between(0.2, 0.4).all()
    assert (slabs["strain reached"] >= 0.07).all() and slabs["modulus, nominal [MPa]"].gt(0).all()
    # A drained cell lets water out under the plates and is softer than the closed one.
    cells = ours[ours["cells"] == 1].set_index("compression L_p")
    assert cells.loc[1e-6, "modulus, nominal [MPa]"] < cells.loc[1e-12, "modulus, nominal [MPa]"]
    # A tissue is compared with the single cell at its own plate speed; none ran at 4 m/s.
    assert (ours["x single cell at 0.05"].notna() == ((ours["cells"] > 1) & (ours["plate [m/s]"] == 1))).all()


def test_page_figures_and_3d_views_are_written_and_the_default_target_is_not(root, tissue_run, tmp_path):
    text = check_target_page(root, tissue_run, "tissue", REDUCED, "tissue.html",
                             ["Tissues against the single cell", "Apparent modulus at small strain",
                              "The paper's conjecture: is a tissue less stiff than one cell?"],
                             [f"tis{i:02d}" for i in range(1, 11)], tmp_path)
    assert "periodic" in text
    # The fresh slab confined and unconfined at 1 m/s, each beside the closed single cell.
    assert "Of 2 periodic slabs beside a single cell" in text
    views = sorted((tissue_run / "report" / "cells").glob("D150_*N8*.data.js"))  # the paper's numerics
    assert len(views) == 2 and '"n_cells": 8' in views[0].read_text()
    slabs = sorted((tissue_run / "report" / "cells").glob("*N16*.data.js"))
    assert len(slabs) == 3 and '"n_cells": 16' in slabs[0].read_text()
