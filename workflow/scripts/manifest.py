"""Snakemake script: the manifest of cases (name, dried state, studies, axis values, case file)."""
import pandas as pd

import _path  # noqa: F401

sm = snakemake  # noqa: F821 (provided by Snakemake)
rows = [{"case": name, "dried": dried, "studies": " ".join(studies), **values, "case_file": case_file, "result": result}
        for name, dried, studies, values, case_file, result in sm.params.cases]
pd.DataFrame(rows).to_csv(sm.output[0], index=False)
