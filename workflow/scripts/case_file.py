"""Snakemake script: writes one case file, the solver's JSON for a case or a dried state of the matrix.
(A script, not a `run:` block: Snakemake 7 spawns `run:` jobs through an unquoted `cd` of the working
directory, which fails in a checkout whose path contains a space.)"""
import _path  # noqa: F401

from analysis import matrix

sm = snakemake  # noqa: F821 (provided by Snakemake)
with open(sm.output[0], "w") as out:
    out.write(matrix.case_json(sm.params.case))
