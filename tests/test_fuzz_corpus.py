"""The fuzzing campaign's kept corpus, replayed (issue 51; scripts/fuzz makes it, tests/fuzz/ holds the
mutations and the rules): mutated case files and --set overrides through `cellsim validate` and a tiny
run, corrupted result files through --from, mutated workflow configs through `snakemake -n`. Every
mutant that once broke a rule is in it (its `defect` says what it was), beside a sample of the campaign
spread over its outcomes. Each must meet every rule (tests/fuzz/rules.py).

The solver's mutants carry the marker `sanitizer`: scripts/test runs them in its sanitizer tier, with
CELLSIM pointing at the build under AddressSanitizer and UndefinedBehaviorSanitizer. scripts/test replays
every defect and every SAMPLE_EVERY-th of the rest; the others carry the marker `full` too, which
scripts/test --all adds (the whole corpus took 5 min of the sanitizer tier and its configs 4 min of the
fast one: most of a sample shares its path through the code with its neighbours)."""
import json
import random

import pytest

from tests.fuzz import config_mutations, file_corruptions, solver_cases
from tests.fuzz.case_mutations import Mutant
from tests.fuzz.config_mutations import ConfigMutant
from tests.fuzz.file_corruptions import FileMutant

from conftest import ROOT

CORPUS = ROOT / "tests" / "fuzz" / "corpus"


def corpus(name):
    return [json.loads(line) for line in (CORPUS / name).read_text().splitlines() if line.strip()]


def label(record):
    return (record.get("defect") or "; ".join(map(str, record["ops"])))[:70]


CASES, FILES, CONFIGS = corpus("cases.jsonl"), corpus("files.jsonl"), corpus("configs.jsonl")
SAMPLE_EVERY = 4


def replayed(records, *marks):
    """The records as parameters: a defect, and every SAMPLE_EVERY-th of the rest, with `marks` only;
    the others with `full` too."""
    return [pytest.param(r, marks=[*marks] + ([] if r.get("defect") or i % SAMPLE_EVERY == 0 else [pytest.mark.full]),
                         id=f"{i}-{label(r)}") for i, r in enumerate(records)]


def test_the_corpus_holds_a_sample_and_every_defect_found():
    assert len(CASES) >= 200 and len(FILES) >= 30 and len(CONFIGS) >= 20
    defects = [r for r in CASES + FILES + CONFIGS if r.get("defect")]
    assert len(defects) >= 10, "the defects the campaign found stay in the corpus"
    outcomes = {r["outcome"] for r in CASES}
    assert {"validate 0 / run 0", "validate 2 / run 2", "validate 0 / run 3"} <= outcomes


@pytest.mark.parametrize("record", replayed(CASES, pytest.mark.sanitizer))
def test_a_case_mutant_meets_every_rule(cellsim, tmp_path, record):
    mutant = Mutant(record["seed"], record["ops"], record["text"], record["overrides"])
    _, _, broken = solver_cases.check_mutant(cellsim, mutant, tmp_path)
    assert broken == [], broken


@pytest.fixture(scope="module")
def corrupter(cellsim, tmp_path_factory):
    """The intact files the corruptions start from (seeded: the campaign's bytes, bit for bit)."""
    return file_corruptions.Corrupter(random.Random(0), cellsim, tmp_path_factory.mktemp("sources"))


@pytest.mark.parametrize("record", replayed(FILES, pytest.mark.sanitizer))
def test_a_corrupted_file_meets_every_rule(corrupter, tmp_path, record):
    mutant = FileMutant(record["seed"], [tuple(op) for op in record["ops"]], salt=record["salt"])
    _, broken = corrupter.check(mutant, tmp_path)
    assert broken == [], broken


@pytest.mark.parametrize("record", replayed(CONFIGS))
def test_a_config_mutant_is_planned_or_refused_naming_its_key(root, tmp_path, record):
    mutant = ConfigMutant(ops=record["ops"], text=record["text"], paths=record["paths"])
    _, broken = config_mutations.check_mutant(root, mutant, tmp_path)
    assert broken == [], broken
