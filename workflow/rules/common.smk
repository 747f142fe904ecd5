# The experiment matrix, computed once when the workflow is parsed (analysis/matrix.py).
import sys

from snakemake.exceptions import WorkflowError

sys.path.insert(0, workflow.basedir)
from analysis import matrix  # noqa: E402

try:
    matrix.check(config, workflow.basedir)
except matrix.ConfigError as error:
    raise WorkflowError(f"config: {error}")

OUT = config["output_dir"]
SOLVER = "build/solver/cellsim"
CASES = matrix.expand(config)  # {case name: Case}, of every target
DRIED = matrix.dried_states(CASES)  # {dried name: case dict}
# The default target runs the studies without a `target`; the others (e.g. convergence) their own.
DEFAULT_CASES = matrix.target_cases(config, CASES)
FIGURES = matrix.target_figures(config)


def job_resources(kind, what, default):
    return config.get("resources", {}).get(kind, {}).get(what, default)


def run_file(case):
    return f"{OUT}/runs/{case}.h5"


def dried_file(dried):
    return f"{OUT}/runs/dried/{dried}.h5"
