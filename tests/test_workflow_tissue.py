"""The tissue target end to end on reduced cells (tests/tissue_reduced.yaml): its runs on two threads,
its table and page, its four figures, the 3-D pages with each cell coloured, and none of the default
target's. Slow: a few minutes on 2 cores."""
import pandas as pd
import pytest

from analysis import matrix
from conftest import CI, run_reduced_target, workflow_config
from figure_checks import check_figures

pytestmark = pytest.mark.slow
REDUCED = "tests/tissue_reduced.yaml"


@pytest.fixture(scope="module")
def tissue_run(root, tmp_path_factory):
    return run_reduced_target(root, tmp_path_factory.mktemp("tissue results"), "tissue", REDUCED,
                              timeout=2400)


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
    page = (tissue_run / "report" / "tissue.html").read_text()
    assert "Tissues against the single cell" in page
    config = workflow_config(root, CI + [REDUCED], tissue_run)
    figures = matrix.target_figures(config, "tissue")
    assert figures == ["tis01", "tis02", "tis03", "tis04"]
    check_figures(config, tissue_run, root, tmp_path, figures)
    for fig in figures:
        assert f"figures/{fig}.png" in page
    views = sorted((tissue_run / "report" / "cells").glob("*N8*.data.js"))
    assert len(views) == 2 and '"n_cells": 8' in views[0].read_text()
    assert not (tissue_run / "figures" / "fig01.png").exists()
    assert not (tissue_run / "report" / "index.html").exists()
