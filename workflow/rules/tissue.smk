# The tissue targets (config: studies with a `target` below, model.md §10), never built by the default
# target: each has its runs, tables, figures and page (results/report/<target>.html).
#   tissue         the closed-cell slab, its single cell and the bounds that fit the hour
#   tissue_bounds  the bound that does not: the quasi-static limit
#   tissue_clusters clusters of 8 and 27 closed cells with free sides
#   tissue_check   the SPH slab beside the closed cells (the check of the closed cells)
#   tissue_large   large slabs for a cluster (workflow/profiles/slurm)
TISSUE_TARGETS = ["tissue", "tissue_bounds", "tissue_clusters", "tissue_check", "tissue_large"]
TISSUE_CASES = {t: matrix.target_cases(config, CASES, t) for t in TISSUE_TARGETS}
TISSUE_FIGURES = {t: matrix.target_figures(config, t) for t in TISSUE_TARGETS}


def tissue_target_inputs(target):
    return {
        "figures": expand(f"{OUT}/figures/{{fig}}.{{ext}}", fig=TISSUE_FIGURES[target], ext=["png", "pdf"]),
        "page": f"{OUT}/report/{target}.html",
        "cells": expand(f"{OUT}/report/cells/{{case}}.html", case=TISSUE_CASES[target]),
        "js": [f"{OUT}/report/js/three.min.js", f"{OUT}/report/js/OrbitControls.js"],
    }


rule tissue:
    input:
        **tissue_target_inputs("tissue"),


rule tissue_bounds:
    input:
        **tissue_target_inputs("tissue_bounds"),


rule tissue_clusters:
    input:
        **tissue_target_inputs("tissue_clusters"),


rule tissue_check:
    input:
        **tissue_target_inputs("tissue_check"),


rule tissue_large:
    input:
        **tissue_target_inputs("tissue_large"),


rule tissue_page:
    input:
        summary=f"{OUT}/tables/{{target}}/summary.csv",
        timeseries=f"{OUT}/tables/{{target}}/timeseries.csv",
        runs=lambda w: [run_file(c) for c in TISSUE_CASES[w.target]],
        figures=lambda w: expand(f"{OUT}/figures/{{fig}}.png", fig=TISSUE_FIGURES[w.target]),
        code="analysis/tissue.py",
    output:
        html=f"{OUT}/report/{{target}}.html",
        table=f"{OUT}/tables/{{target}}/tissue.csv",
    wildcard_constraints:
        target="|".join(TISSUE_TARGETS),
    script:
        "../scripts/tissue.py"
