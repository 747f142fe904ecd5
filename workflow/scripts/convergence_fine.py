"""Snakemake script: the closed cell's four-level ladder and its membrane anchor, written and printed."""
import _path  # noqa: F401
from analysis import convergence_fine, matrix

sm = snakemake  # noqa: F821 (provided by Snakemake)
cases = matrix.expand(sm.config)
for study, paths, output, tabulate in ((convergence_fine.WALL, sm.input.wall, sm.output.ladder, convergence_fine.ladder),
                                       (convergence_fine.MEMBRANE, sm.input.membrane, sm.output.membrane,
                                        convergence_fine.membrane)):
    listed = convergence_fine.runs_of(cases, study)  # the rule's inputs, in this order
    table = tabulate([(case, level, path) for (case, level), path in zip(listed, paths)])
    table.to_csv(output, index=False)
    print(table.to_string(index=False))
