# The paper's two named extensions (config: studies with `target: extensions`, docs/model.md §3b-§3c):
# load-unload loops of the elastic-plastic wall, and seeded heterogeneous ensembles. Built by
# `snakemake --cores 2 extensions`, never by the default target; their homogeneous elastic cells are the
# paper's baseline cases, shared with it.
EXTENSION_CASES = matrix.target_cases(config, CASES, "extensions")
EXTENSION_FIGURES = matrix.target_figures(config, "extensions")


rule extensions:
    input:
        figures=expand(f"{OUT}/figures/{{fig}}.{{ext}}", fig=EXTENSION_FIGURES, ext=["png", "pdf"]),
        page=f"{OUT}/report/extensions.html",


rule extensions_page:
    input:
        summary=f"{OUT}/tables/extensions/summary.csv",
        timeseries=f"{OUT}/tables/extensions/timeseries.csv",
        figures=expand(f"{OUT}/figures/{{fig}}.png", fig=EXTENSION_FIGURES),
        code=["analysis/extensions.py", "analysis/ensembles.py"],
    output:
        html=f"{OUT}/report/extensions.html",
        tables=directory(f"{OUT}/tables/extensions/page"),
    script:
        "../scripts/extensions.py"
