"""The tissue target end to end on reduced cells (tests/tissue_reduced.yaml): its runs on two threads,
its table and page, its four figures, the 3-D pages with each cell coloured, and none of the default
target's. Slow: a few minutes on 2 cores."""
import pandas as pd
import pytest

from conftest import check_target_page, reduced_target_fixture

pytestmark = pytest.mark.slow
REDUCED = "tests/tissue_reduced.yaml"
tissue_run = reduced_target_fixture("tissue", REDUCED)


def test_tissue_table_compares_each_tissue_with_the_single_cell(tissue_run):
    table = pd.read_csv(tissue_run / "tables" / "tissue" / "tissue.csv")
    assert sorted(zip(table["cells"], table["X/X0"])) == [(1, 0.5), (1, 1.0), (8, 0.5), (8, 1.0)]
    tissues = table[table["cells"] == 8]
    assert tissues["porosity (dried)"].between(0.05, 0.6).all()
    # Fresh: the cells stay bonded while drying (nothing to pull them apart), and all of it is counted.
    fresh = tissues[tissues["X/X0"] == 1.0].iloc[0]
    assert fresh["bonds"] > 500 and fresh["broken in drying"] == 0
    assert fresh["broken between layers"] + fresh["broken on lateral faces"] == fresh["broken in compression"]
    assert (tissues["stress at 0.05 [kPa]"] > 0).all() and tissues["x single cell at 0.05"].notna().all()


def test_page_figures_and_3d_views_are_written_and_the_default_target_is_not(root, tissue_run, tmp_path):
    check_target_page(root, tissue_run, "tissue", REDUCED, "tissue.html", ["Tissues against the single cell"],
                      ["tis01", "tis02", "tis03", "tis04"], tmp_path)
    views = sorted((tissue_run / "report" / "cells").glob("*N8*.data.js"))
    assert len(views) == 2 and '"n_cells": 8' in views[0].read_text()
