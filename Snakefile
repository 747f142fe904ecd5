# Regenerates the paper's study: build the solver, dry each distinct cell once, compress every case
# from its dried state, aggregate, draw every figure, write the report.
#   snakemake --cores 2                               the paper's study (config/config.yaml)
#   snakemake --cores 2 --configfile config/ci.yaml   the same studies, reduced (minutes)
from snakemake.utils import min_version, validate

min_version("7.21")

configfile: "config/config.yaml"

validate(config, "config/schema/config.schema.yaml")


include: "workflow/rules/common.smk"

# On a cluster (workflow/profiles/slurm) only the solver runs go to the scheduler; building,
# bookkeeping, figures and the report are quick and run where snakemake runs.
localrules: all, build_solver, case_file, dried_case_file, manifest, aggregate, figure, report


include: "workflow/rules/solver.smk"
include: "workflow/rules/runs.smk"
include: "workflow/rules/analysis.smk"


rule all:
    default_target: True
    input:
        figures=expand(f"{OUT}/figures/{{fig}}.{{ext}}", fig=FIGURES, ext=["png", "pdf"]),
        report=f"{OUT}/report/index.html",
        manifest=f"{OUT}/manifest.csv",
        tables=[f"{OUT}/tables/timeseries.csv", f"{OUT}/tables/summary.csv"],
