"""A config that breaks its schema is told in one line naming the key's path (analysis/config_errors.py), as
cellsim tells a bad case key; the workflow's dry runs in test_workflow_config.py check the same end to end."""
import copy

import pytest

from analysis import config_errors, matrix


@pytest.fixture(scope="module")
def config(root):
    return matrix.workflow_config([], root)


@pytest.fixture(scope="module")
def schema(root):
    return root / "config" / "schema" / "config.schema.yaml"


def with_change(config, section, key, value):
    changed = copy.deepcopy(config)
    changed["base"][section][key] = value
    return changed


def test_the_shipped_config_passes(config, schema):
    assert config_errors.problem(config, schema) is None


@pytest.mark.parametrize("section, key, value, message", [
    ("cell", "turgor_kPA", 150, "base.cell: unknown key 'turgor_kPA'; did you mean 'turgor_kPa'?"),
    ("wall", "G_Mpa", 18, "base.wall: unknown key 'G_Mpa'; did you mean 'G_MPa'?"),
    ("cell", "diameter", 150, "base.cell: unknown key 'diameter'; did you mean 'diameter_um'?"),
    ("cell", "colour", "red", "base.cell: unknown key 'colour'; known keys: diameter_um, fill_gap_um"),
    ("drying", "dryness", 1.5, "base.drying.dryness: 1.5 is greater than the maximum of 1.0"),
    ("cell", "n_wall", "many", "base.cell.n_wall: 'many' is not of type 'integer'"),
])
def test_a_bad_key_or_value_is_one_line_naming_it(config, schema, section, key, value, message):
    said = config_errors.problem(with_change(config, section, key, value), schema)
    assert said.startswith(message) and "\n" not in said and len(said) < 300


def test_a_misspelt_top_level_key_is_named(config, schema):
    changed = {**config, "figurs": {}}
    assert config_errors.problem(changed, schema) == "the config: unknown key 'figurs'; did you mean 'figures'?"
