# The convergence studies (config: studies with `target: convergence`): their runs, tables, figures
# and page, built by `snakemake --cores 2 convergence`, never by the default target.
from analysis import convergence, numerical_band  # noqa: E402

CONVERGENCE_CASES = matrix.target_cases(config, CASES, "convergence")
CONVERGENCE_FIGURES = matrix.target_figures(config, "convergence")


rule convergence:
    input:
        figures=expand(f"{OUT}/figures/{{fig}}.{{ext}}", fig=CONVERGENCE_FIGURES, ext=["png", "pdf"]),
        page=f"{OUT}/report/convergence.html",


rule convergence_page:
    input:
        summary=f"{OUT}/tables/convergence/summary.csv",
        anchors=f"{OUT}/tables/convergence/anchors.csv",
        figures=expand(f"{OUT}/figures/{{fig}}.png", fig=CONVERGENCE_FIGURES),
        code="analysis/convergence.py",
    output:
        html=f"{OUT}/report/convergence.html",
        table=f"{OUT}/tables/convergence/convergence.csv",
    script:
        "../scripts/convergence.py"


rule convergence_anchors:
    input:
        runs=[run_file(c) for _, c, _ in convergence.anchor_runs(config, CASES)],
        code="analysis/anchors.py",
    output:
        table=f"{OUT}/tables/convergence/anchors.csv",
    script:
        "../scripts/anchors.py"


# The default figures' numerical band: the LJ ladder alone (study convergence_resolution), its table to be
# copied to config `numerical_band.file` (analysis/numerical_band.py).
rule numerical_band:
    input:
        runs=[run_file(c) for c in CASES if numerical_band.STUDY in CASES[c].studies],
        code="analysis/numerical_band.py",
    output:
        table=f"{OUT}/tables/numerical_band/lj_ladder.csv",
    script:
        "../scripts/numerical_band.py"
