"""The tissue target end to end on reduced cells (tests/tissue_reduced.yaml): its runs (one thread
each), its table and page (the periodic slab of closed cells beside its single cell, the bounds beside
them), its seven figures, the 3-D pages with each cell coloured, and none of the default target's. Slow:
about two minutes on 2 cores."""
import pandas as pd
import pytest

from conftest import check_target_page, reduced_target_fixture

pytestmark = pytest.mark.slow
REDUCED = "tests/tissue_reduced.yaml"
tissue_run = reduced_target_fixture("tissue", REDUCED)


def test_the_slab_of_closed_cells_beside_its_cell_and_the_bounds(tissue_run):
    table = pd.read_csv(tissue_run / "tables" / "tissue" / "tissue.csv")
    assert sorted(zip(table["cells"], table["sides"], table["compression L_p"])) == [
        (1, "free", 1e-12)] * 4 + [(1, "free", 1e-6), (16, "confined", 1e-12), (16, "confined", 1e-12),
                                   (16, "unconfined", 1e-12)]
    assert table["numerics"].str.startswith("closed cells, dynamic").all()
    slabs = table[table["cells"] == 16]
    # Fresh, built from a lattice: nothing breaks in drying, the period's footprint holds the cells.
    assert (slabs["broken in drying"] == 0).all() and slabs["porosity (dried)"].between(0.2, 0.4).all()
    assert (slabs["strain reached"] >= 0.07).all() and slabs["modulus, nominal [MPa]"].gt(0).all()
    # Every stage's energy account closes within the solver's tolerance, the period's loss counted: the
    # unconfined slab's period follows under the plates too, the confined one's only in drying.
    assert table["energy residual, drying / flows"].abs().max() < 0.02
    assert table["energy residual, compression / plate work"].abs().max() < 0.02
    assert (slabs["period loss, drying [nJ]"] > 0).all()
    assert (slabs.set_index("sides").loc["unconfined", "period loss, compression [nJ]"] > 0)
    # A drained cell lets water out under the plates and is softer than the sealed one.
    cells = table[(table["cells"] == 1) & (table["numerics"] == table["numerics"].iloc[0])]
    assert cells.set_index("compression L_p").loc[1e-6, "modulus, nominal [MPa]"] < \
        cells.set_index("compression L_p").loc[1e-12, "modulus, nominal [MPa]"]
    # Each slab meets the single cell of its own numerics (the thick wall's beside the thick cell).
    assert slabs["x single cell at 0.05"].notna().all()


def test_page_figures_and_3d_views_are_written_and_the_default_target_is_not(root, tissue_run, tmp_path):
    text = check_target_page(root, tissue_run, "tissue", REDUCED, "tissue.html",
                             ["Tissues against the single cell", "The slab against its cell",
                              "Apparent modulus at small strain",
                              "The paper's conjecture: is a tissue less stiff than one cell?"],
                             [f"tis{i:02d}" for i in range(1, 8)], tmp_path)
    assert "periodic" in text and "initial tangent modulus, as published" in text
    # The fresh slab confined and unconfined, and the thick-walled one, each beside its closed single cell.
    assert "Of 3 periodic slabs beside a single cell" in text
    assert "the closest case run here" not in text  # no drained slab ran in the reduced study
    slabs = sorted((tissue_run / "report" / "cells").glob("*N16*.data.js"))
    assert len(slabs) == 3 and '"n_cells": 16' in slabs[0].read_text()
