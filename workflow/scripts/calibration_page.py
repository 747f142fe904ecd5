"""Snakemake script: the calibrate target's page (analysis/calibration_page.py)."""
import json
import pathlib

import pandas as pd

import _path  # the analysis package importable; the rule's files by name
from analysis import calibration_page

sm = snakemake  # noqa: F821 (provided by Snakemake)
tables = {name: pd.read_csv(getattr(sm.input, name)) for name in ("judged", "posterior", "predictive", "confirm", "recovery")}
diagnostics = json.loads(pathlib.Path(sm.input.diagnostics).read_text())
calibration_page.write(sm.output.html, sm.config, tables, diagnostics,
                       {"calibration_posterior": sm.input.posterior_png, "calibration_predictive": sm.input.predictive_png})
