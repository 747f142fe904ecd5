# The experiment matrix, computed once when the workflow is parsed (analysis/matrix.py).
import os
import sys

from snakemake.exceptions import WorkflowError

sys.path.insert(0, workflow.basedir)
from analysis import calibration, columns, comparison, matrix  # noqa: E402
from analysis.figures import render  # noqa: E402

try:
    matrix.check(config, workflow.basedir)
    if "calibration" in config:
        calibration.check(config)  # a target without its uncertainty, an unknown without a prior range
    CASES = matrix.expand(config)  # {case name: Case}, of every target
    REST = matrix.rest_states(CASES)  # {rest name: case dict}: each cell settled once, for all its dryness levels
except (matrix.ConfigError, calibration.CalibrationError) as error:
    raise WorkflowError(f"config: {error}")

OUT = config["output_dir"]
SOLVER = "build/solver/cellsim"
DRIED = matrix.dried_states(CASES)  # {dried name: case dict}
REST_OF = {case.dried: case.rest for case in CASES.values()}  # dried name -> its state at rest
# The default target runs the studies without a `target`; the others (e.g. convergence) their own.
DEFAULT_CASES = matrix.target_cases(config, CASES)
FIGURES = matrix.target_figures(config)


def job_resources(kind, what, default):
    return config.get("resources", {}).get(kind, {}).get(what, default)


def run_resources(kind, case, what, default):
    """A run's threads, memory or time: a tissue's (a case of more than one cell) from `tissue`, any
    other from its kind (dry, compress)."""
    cells = 1
    for axis in ("cells_x", "cells_y", "cells_z"):
        cells *= case.get("tissue", {}).get(axis, 1)
    return job_resources("tissue" if cells > 1 else kind, what, default)


def case_file(case):
    return f"{OUT}/cases/{case}.json"


def run_file(case):
    return f"{OUT}/runs/{case}.h5"


def dried_file(dried):
    return f"{OUT}/runs/dried/{dried}.h5"


def rest_file(rest):
    return f"{OUT}/runs/rest/{rest}.h5"
