"""Snakemake script: a design study's runs as one table (analysis/design_runs.py)."""
import _path  # the analysis package importable; the rule's files by name
from analysis import design_runs, matrix

sm = snakemake  # noqa: F821 (provided by Snakemake)
config, study = sm.config, sm.wildcards.study
cases = matrix.expand(config)
by_name = _path.by_name(sm.input.runs)
names = [c for c in matrix.target_cases(config, cases, matrix.target_of(config, study)) if study in cases[c].studies]
compressed = all(c in by_name for c in names)
files = {c: by_name[c] if compressed else by_name[cases[c].dried] for c in names}
design_runs.table(config, study, cases, files, compressed).to_csv(sm.output[0], index=False)
