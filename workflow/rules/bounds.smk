# The rate and drainage bounds of config/converged.yaml (studies with `target: converged_bounds`), moved out
# of that file's default target to keep it within two hours on 2 cores (issue 66's rule): their runs,
# figures and page (results-converged/report/converged_bounds.html), built by
#   snakemake --cores 2 --configfile config/converged.yaml converged_bounds
BOUNDS_CASES = matrix.target_cases(config, CASES, "converged_bounds")
BOUNDS_FIGURES = matrix.target_figures(config, "converged_bounds")


rule converged_bounds:
    input:
        figures=expand(f"{OUT}/figures/{{fig}}.{{ext}}", fig=BOUNDS_FIGURES, ext=["png", "pdf"]),
        page=f"{OUT}/report/converged_bounds.html",


rule converged_bounds_page:
    input:
        summary=f"{OUT}/tables/converged_bounds/summary.csv",
        figures=expand(f"{OUT}/figures/{{fig}}.png", fig=BOUNDS_FIGURES),
        code="analysis/bounds.py",
    output:
        html=f"{OUT}/report/converged_bounds.html",
    script:
        "../scripts/bounds.py"
