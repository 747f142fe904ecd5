# The tissue studies (config: studies with `target: tissue`, model.md §10): their runs, tables, figures
# and page, built by `snakemake --cores 2 tissue`, never by the default target. Their single cells are
# the paper's baseline cases, shared with the default target.
TISSUE_CASES = matrix.target_cases(config, CASES, "tissue")
TISSUE_FIGURES = matrix.target_figures(config, "tissue")


rule tissue:
    input:
        figures=expand(f"{OUT}/figures/{{fig}}.{{ext}}", fig=TISSUE_FIGURES, ext=["png", "pdf"]),
        page=f"{OUT}/report/tissue.html",
        cells=expand(f"{OUT}/report/cells/{{case}}.html", case=TISSUE_CASES),
        js=[f"{OUT}/report/js/three.min.js", f"{OUT}/report/js/OrbitControls.js"],


rule aggregate_tissue:
    input:
        runs=[run_file(c) for c in TISSUE_CASES],
    output:
        timeseries=f"{OUT}/tables/tissue/timeseries.csv",
        summary=f"{OUT}/tables/tissue/summary.csv",
    script:
        "../scripts/aggregate.py"


rule tissue_page:
    input:
        summary=f"{OUT}/tables/tissue/summary.csv",
        timeseries=f"{OUT}/tables/tissue/timeseries.csv",
        runs=[run_file(c) for c in TISSUE_CASES],
        figures=expand(f"{OUT}/figures/{{fig}}.png", fig=TISSUE_FIGURES),
        code="analysis/tissue.py",
    output:
        html=f"{OUT}/report/tissue.html",
        table=f"{OUT}/tables/tissue/tissue.csv",
    script:
        "../scripts/tissue.py"
