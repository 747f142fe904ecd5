"""For the Snakemake scripts: the repository's `analysis` package importable, and a rule's files by name."""
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))


def by_name(paths):
    """The files a rule lists (figures, runs), by name ("fig07", a case), in the rule's order."""
    return {pathlib.Path(p).stem: p for p in paths}
