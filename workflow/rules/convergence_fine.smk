# The closed cell's ladder to level 4 and its membrane anchor (studies with `target: convergence_fine`):
# `snakemake --cores 2 convergence_fine`, never by the default target (analysis/convergence_fine.py).
from analysis import convergence_fine  # noqa: E402

FINE_RUNS = {study: convergence_fine.runs_of(CASES, study) for study in (convergence_fine.WALL, convergence_fine.MEMBRANE)}


rule convergence_fine:
    input:
        figures=expand(f"{OUT}/figures/{{fig}}.{{ext}}", fig=matrix.target_figures(config, "convergence_fine"),
                       ext=["png", "pdf"]),
        ladder=f"{OUT}/tables/convergence_fine/ladder.csv",


rule convergence_fine_tables:
    input:
        wall=[run_file(case) for case, _ in FINE_RUNS[convergence_fine.WALL]],
        membrane=[run_file(case) for case, _ in FINE_RUNS[convergence_fine.MEMBRANE]],
        code="analysis/convergence_fine.py",
    output:
        ladder=f"{OUT}/tables/convergence_fine/ladder.csv",
        membrane=f"{OUT}/tables/convergence_fine/membrane.csv",
    script:
        "../scripts/convergence_fine.py"
