"""Regression: reduced cases against stored reference values (tests/regression/reference.json),
each quantity within its stated tolerance (tests/regression/cases.json says why). CI never
regenerates the references; scripts/regenerate-regression does, on purpose."""
import json
import math

import pytest

from regression_runs import HERE, measure, spec


@pytest.fixture(scope="module")
def measured(cellsim, tmp_path_factory):
    return measure(cellsim, tmp_path_factory.mktemp("regression"))


def within(stored, new, tolerance):
    if "absolute" in tolerance:
        return abs(new - stored) <= tolerance["absolute"], f"{tolerance['absolute']} absolute"
    return abs(new - stored) <= tolerance["relative"] * abs(stored), f"{tolerance['relative']:.1%} relative"


@pytest.mark.parametrize("case", sorted(spec()["cases"]))
def test_matches_stored_reference(measured, case):
    reference = json.loads((HERE / "reference.json").read_text())["values"][case]
    tolerances = spec()["tolerances"]
    failures = []
    for quantity, tolerance in tolerances.items():
        stored, new = reference[quantity], measured[case][quantity]
        ok, allowed = within(stored, new, tolerance)
        if not (ok and math.isfinite(new)):
            failures.append(f"{case}: {quantity} stored {stored:.6g}, new {new:.6g}, tolerance {allowed}")
    assert not failures, "results moved:\n" + "\n".join(failures)


def test_reference_covers_every_case_and_quantity():
    reference = json.loads((HERE / "reference.json").read_text())
    assert set(reference["values"]) == set(spec()["cases"])
    for values in reference["values"].values():
        assert set(values) == set(spec()["tolerances"])
