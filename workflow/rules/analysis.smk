# Manifest, tidy tables, one job per figure, and the report.
rule manifest:
    output:
        f"{OUT}/manifest.csv",
    params:
        cases=lambda w: [(c.name, c.dried, c.studies, c.values) for c in CASES.values()],
    script:
        "../scripts/manifest.py"


rule aggregate:
    input:
        runs=[run_file(c) for c in CASES],
    output:
        timeseries=f"{OUT}/tables/timeseries.csv",
        summary=f"{OUT}/tables/summary.csv",
    script:
        "../scripts/aggregate.py"


def figure_inputs(wildcards):
    names = matrix.figure_cases(config, wildcards.fig, CASES)
    runs = [run_file(n) for n in names]
    dried = sorted({dried_file(CASES[n].dried) for n in names})
    refs = [config["references"][r]["file"] for r in config["figures"][wildcards.fig].get("references", [])]
    return {"runs": runs, "dried": dried, "references": refs}


rule figure:
    input:
        unpack(figure_inputs),
    output:
        png=f"{OUT}/figures/{{fig}}.png",
        pdf=f"{OUT}/figures/{{fig}}.pdf",
    params:
        spec=lambda w: config["figures"][w.fig],
    script:
        "../scripts/figure.py"


rule report:
    input:
        summary=f"{OUT}/tables/summary.csv",
        timeseries=f"{OUT}/tables/timeseries.csv",
        figures=expand(f"{OUT}/figures/{{fig}}.png", fig=FIGURES),
        sources=["paper/report_intro.md", "docs/model-closures.md"],
    output:
        html=f"{OUT}/report/index.html",
        claims=f"{OUT}/tables/claims.csv",
    script:
        "../scripts/report.py"
