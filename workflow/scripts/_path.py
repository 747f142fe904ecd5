"""Makes the repository's `analysis` package importable from Snakemake scripts."""
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
