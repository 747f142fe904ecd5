"""Snakemake script: the manifest of cases (name, dried state, studies, axis values, case file)."""
import pandas as pd

import _path  # noqa: F401

sm = snakemake  # noqa: F821 (provided by Snakemake)
rows = [{"case": name, "dried": dried, "studies": " ".join(studies), **values,
         "case_file": f"{sm.config['output_dir']}/cases/{name}.json",
         "result": f"{sm.config['output_dir']}/runs/{name}.h5"}
        for name, dried, studies, values in sm.params.cases]
pd.DataFrame(rows).to_csv(sm.output[0], index=False)
