# Regenerates the paper's study: build the solver, dry each distinct cell once, compress every case
# from its dried state, aggregate, draw every figure, write the report.
#   snakemake --cores 2                               the paper's study (config/config.yaml)
#   snakemake --cores 2 --configfile config/ci.yaml   the same studies, reduced (minutes)
#   snakemake --cores 2 convergence                   resolution and time-step convergence (not default)
#   snakemake --cores 2 convergence_fine              the closed cell and its membrane anchor at levels 1-4
#   snakemake --cores 2 numerical_band                the LJ ladder alone: the default figures' band
#   snakemake --cores 2 tissue                        a slab of closed cells against one cell (not default;
#                                                     also tissue_bounds, tissue_check, tissue_large)
#   snakemake --cores 2 extensions                    elastic-plastic wall, heterogeneous ensembles (not default)
#   snakemake --cores 2 sensitivity                   a Sobol design, its emulators, Sobol indices, a slider page
#   snakemake --cores 2 calibrate                     the wall's unknowns given measured numbers (a posterior)
#   snakemake --cores 2 --configfile config/converged.yaml [converged_bounds]
#                                                     the paper's claims judged three ways [the rate and drainage bounds]
from snakemake.exceptions import WorkflowError
from snakemake.utils import min_version, validate

min_version("7.21")

# What --configfile gave, before config/config.yaml is merged under it: a value where config.yaml has a
# mapping (or the reverse) would stop Snakemake's own merge with a TypeError naming no key.
import sys as _sys
import yaml as _yaml
_sys.path.insert(0, workflow.basedir)
from analysis.matrix import ConfigError as _ConfigError, check_merge as _check_merge  # noqa: E402
try:
    _check_merge(config, _yaml.safe_load(open(f"{workflow.basedir}/config/config.yaml")))
except _ConfigError as error:
    raise WorkflowError(f"config: {error}")

configfile: "config/config.yaml"

# workflow/profiles/slurm is a Snakemake 7 profile (--cluster); Snakemake 8+ reads its config.v8+.yaml,
# which sets this key so that the run stops here with the way forward instead of an obscure failure.
if config.pop("slurm_profile_needs_snakemake_7", False):
    raise WorkflowError(
        "workflow/profiles/slurm works with Snakemake 7.x only (it submits through --cluster, which "
        "Snakemake 8 removed). With Snakemake 8 or later, install the SLURM executor plugin "
        "(snakemake-executor-plugin-slurm) and run: snakemake --executor slurm --jobs 100 "
        "--default-resources slurm_partition=<partition> slurm_account=<account> "
        "[--configfile my.yaml]; the rules already give each job threads, mem_mb and runtime (minutes) "
        "from the config's `resources`. See README, 'Running on a SLURM cluster'.")

# A key the schema does not know, or a bad value, stops here in one line naming it ("did you mean ...?");
# Snakemake's validate, which would print the schema around it, then only sets the schema's defaults.
from analysis import config_errors as _config_errors  # noqa: E402
_problem = _config_errors.problem(config, f"{workflow.basedir}/config/schema/config.schema.yaml")
if _problem:
    raise WorkflowError(f"config: {_problem}")
validate(config, "config/schema/config.schema.yaml")


include: "workflow/rules/common.smk"

# On a cluster (workflow/profiles/slurm) only the solver runs go to the scheduler; building,
# bookkeeping, figures and the report are quick and run where snakemake runs.
localrules: all, build_solver, case_file, dried_case_file, rest_case_file, manifest, aggregate, figure, report, three_js, cell_view, \
    convergence, aggregate_target, convergence_page, numerical_band, convergence_fine, convergence_fine_tables, tissue, tissue_bounds, tissue_clusters, tissue_check, \
    tissue_large, tissue_page, \
    extensions, extensions_page, converged_bounds, converged_bounds_page, design_table, sensitivity, sensitivity_analysis, calibrate, calibration_posterior, calibration_page


include: "workflow/rules/solver.smk"
include: "workflow/rules/runs.smk"
include: "workflow/rules/analysis.smk"
include: "workflow/rules/convergence.smk"
include: "workflow/rules/convergence_fine.smk"
include: "workflow/rules/tissue.smk"
include: "workflow/rules/extensions.smk"
include: "workflow/rules/bounds.smk"
include: "workflow/rules/sensitivity.smk"


rule all:
    default_target: True
    input:
        figures=expand(f"{OUT}/figures/{{fig}}.{{ext}}", fig=FIGURES, ext=["png", "pdf"]),
        report=f"{OUT}/report/index.html",
        manifest=f"{OUT}/manifest.csv",
        tables=[f"{OUT}/tables/timeseries.csv", f"{OUT}/tables/summary.csv"],
