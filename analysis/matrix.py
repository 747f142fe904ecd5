"""The experiment matrix: studies in config -> cases with readable, stable names.

A case is `base` with the values of every axis set; its name lists every axis as label+value,
in the order of the labels (e.g. D150_G18_P200_t6_v1_X0.5), so names are stable when studies are
added or removed, whatever order config files list the axes in, and identical cases of different
studies coincide. An axis appears in a name only where its value differs from base (so adding an axis
renames no existing case and reruns nothing), unless it sets `hide_base_value: false`, as the paper's
axes do (their names say every value: D150_G18_P200_t6_v1_X0.5). An axis without a key (a resolution
level, say) sets only its `coupled` keys, and its value at base is `base_value`. Coupled keys are
set after every axis's own key, and a hidden axis's value is read back from the finished case, so
a name always says what the case runs. The dried state of a case is the same name
without the axes that only touch the compression stage; its state at rest (the settled cell it dries
from) is the dried name without the dryness as well, so that one settle serves every dryness.

Every case is complete: a key that neither base nor an axis sets takes the solver's default (from
config/schema/case.schema.json), so the case file of a case does not change when base comes to name
a key at its default value (as adding an axis asks), and nothing reruns for it.

A study with a `target` (convergence, tissue, extensions) is not part of the default target (`snakemake --cores 2`);
it runs with `snakemake --cores 2 <target>`.
"""
import copy
import functools
import itertools
import json
import pathlib
from dataclasses import dataclass, field

import jsonschema
import yaml

from analysis import design
from analysis.quantities import DRAWABLE, MODULI  # the solver's time series, those derived, the moduli


class ConfigError(ValueError):
    """A config that passes the schema but is inconsistent (names the key)."""


@dataclass
class Case:
    name: str
    dried: str
    rest: str                        # the state at rest it dries from (rest_case)
    values: dict                     # axis -> value
    case: dict                       # the full cellsim case (nested, file units)
    studies: list = field(default_factory=list)


def fmt(value):
    """A value as it appears in names: 1.0 -> 1, 0.18 -> 0.18, 2.5e-6 -> 2.5e-06; a name as it is."""
    return value if isinstance(value, str) else f"{value:g}"


def get_key(case, key):
    section, name = key.split(".", 1)
    return case.get(section, {}).get(name)


def set_key(case, key, value):
    section, name = key.split(".", 1)
    case.setdefault(section, {})[name] = value


DEFAULT_TARGET = "all"


def axis_keys(spec):
    """Every case key an axis sets: its own key and those of its coupled values."""
    keys = [spec["key"]] if "key" in spec else []
    for coupled in spec.get("coupled", {}).values():
        keys += [k for k in coupled if k not in keys]
    return keys


def is_compression_only(spec):
    keys = axis_keys(spec)
    return bool(keys) and all(k.startswith("compression.") for k in keys)


# The keys a state at rest may differ in from the drying that continues it (cellsim run --from; at
# t = 0 the drying ramp is 0, so the settle does not see them): solver/src/cli/run.cpp, may_differ.
REST_FREE_KEYS = ("drying.dryness", "drying.steps")


def is_drying_only(spec):
    keys = axis_keys(spec)
    return bool(keys) and all(k in REST_FREE_KEYS for k in keys)


def rest_case(case):
    """The run that settles a case's cell and stops: dryness 1, no drying, no compression (whose keys
    the settle does not see, so cases that differ only there share it)."""
    rest = copy.deepcopy(case)
    set_key(rest, "drying.dryness", 1.0)
    set_key(rest, "drying.steps", 0)
    rest["compression"] = {"steps": 0}
    return rest


def base_value(config, axis):
    spec = config["axes"][axis]
    return get_key(config["base"], spec["key"]) if "key" in spec else spec.get("base_value")


def target_of(config, study):
    return config["studies"][study].get("target", DEFAULT_TARGET)


def targets(config):
    """The targets other than the default that the config's studies name, in order."""
    return sorted({target_of(config, s) for s in config["studies"]} - {DEFAULT_TARGET})


def target_cases(config, cases, target=DEFAULT_TARGET):
    """Names of the cases a target runs: those of its studies."""
    studies = {s for s in config["studies"] if target_of(config, s) == target}
    return [c.name for c in cases.values() if studies & set(c.studies)]


def figure_studies(spec):
    """A figure's studies: `study` names one, or lists several whose cases it draws together."""
    return spec["study"] if isinstance(spec["study"], list) else [spec["study"]]


def target_figures(config, target=DEFAULT_TARGET):
    return [f for f, spec in config["figures"].items() if target_of(config, figure_studies(spec)[0]) == target]


def check_merge(override, base, path=()):
    """A --configfile is merged over config/config.yaml mapping by mapping; where one of the two has a
    mapping and the other a value, Snakemake's own merge stops with a TypeError that names no key. Raises
    ConfigError naming the first such key instead (found issue 51, by the config fuzzer)."""
    for key, value in override.items():
        if key not in base:
            continue
        where = ".".join(map(str, path + (key,)))
        if isinstance(base[key], dict) != isinstance(value, dict):
            has = "a mapping" if isinstance(base[key], dict) else f"the value {base[key]!r}"
            raise ConfigError(f"{where} = {str(value)[:60]!r}: config/config.yaml has {has} there, and a "
                              f"--configfile must give the same kind (a mapping is merged key by key)")
        if isinstance(value, dict):
            check_merge(value, base[key], path + (key,))


def check(config, root="."):
    """Cross-references the schema cannot check; raises ConfigError naming the key."""
    axes, studies = config["axes"], config["studies"]
    for axis, spec in axes.items():
        if "key" in spec and get_key(config["base"], spec["key"]) is None:
            raise ConfigError(f"axes.{axis}: base has no value for its key '{spec['key']}' (add it to base)")
        if "key" not in spec and ("base_value" not in spec or "coupled" not in spec):
            raise ConfigError(f"axes.{axis}: an axis without a key needs base_value and coupled (the keys each "
                              "value sets)")
    keyed = [(axis, spec["key"]) for axis, spec in axes.items() if "key" in spec]
    for i, (axis, key) in enumerate(keyed):
        other = next((a for a, k in keyed[:i] if k == key), None)
        if other:
            raise ConfigError(f"axes.{axis}: its key '{key}' is axis {other}'s too: two axes cannot set one key")
    labels = [spec["label"] for spec in axes.values()]
    if len(set(labels)) != len(labels):
        raise ConfigError(f"axes: labels must be distinct, got {labels}")
    for study, spec in studies.items():
        if "design" in spec:
            try:
                design.check(study, spec["design"], axes)
            except design.DesignError as error:
                raise ConfigError(str(error)) from error
            both = sorted(set(spec["vary"]) & set(spec["design"]["factors"]))
            if both:
                raise ConfigError(f"studies.{study}: {both} both varied and a design's factors; name each in one")
        for axis in spec["vary"]:
            if axis not in axes:
                raise ConfigError(f"studies.{study}.vary.{axis}: unknown axis; known: {sorted(axes)}")
            if "key" not in axes[axis]:
                known = [fmt(axes[axis]["base_value"])] + list(axes[axis]["coupled"])
                for value in spec["vary"][axis]:
                    if fmt(value) not in known:
                        raise ConfigError(f"studies.{study}.vary.{axis}: value {fmt(value)} is not one of the "
                                          f"axis's values {known} (axes.{axis}.coupled names them)")
                check_labels(config, study, axis)
    references, shrinkage = config.get("references", {}), config.get("shrinkage_references", {})
    for section, entries in (("references", references), ("shrinkage_references", shrinkage)):
        for ref, spec in entries.items():
            if not (pathlib.Path(root) / spec["file"]).is_file():
                raise ConfigError(f"{section}.{ref}.file: no such file '{spec['file']}'")
    band = config.get("numerical_band")
    if band and not (pathlib.Path(root) / band["file"]).is_file():
        raise ConfigError(f"numerical_band.file: no such file '{band['file']}' (snakemake --cores 2 numerical_band "
                          "writes it under tables/numerical_band/)")
    for fig, spec in config["figures"].items():
        where = f"figures.{fig}"
        for study in figure_studies(spec):
            if study not in studies:
                raise ConfigError(f"{where}.study: unknown study '{study}'; known: {sorted(studies)}")
        if len({target_of(config, s) for s in figure_studies(spec)}) > 1:
            raise ConfigError(f"{where}.study: its studies {figure_studies(spec)} belong to different targets")
        for axis in spec.get("where", {}):
            if axis not in axes:
                raise ConfigError(f"{where}.where.{axis}: unknown axis; known: {sorted(axes)}")
        lines = spec.get("lines", [])
        for key in ["panels", "rows", "cols"] + (["lines"] if isinstance(lines, str) else []):
            axis = spec.get(key)
            if axis is not None and axis != "moment" and axis not in axes:
                raise ConfigError(f"{where}.{key}: unknown axis '{axis}'; known: {sorted(axes)}")
        for axis in (lines if isinstance(lines, list) else []):
            if axis not in axes:
                raise ConfigError(f"{where}.lines: unknown axis '{axis}'; known: {sorted(axes)}")
        if spec["family"] == "modulus":
            if not spec.get("y") or not set(spec["y"]) <= set(MODULI) or "lines" not in spec:
                raise ConfigError(f"{where}: a modulus figure needs lines and y among {sorted(MODULI)}")
        for q in [spec.get("x")] + (spec.get("y", []) if spec["family"] != "modulus" else []):
            if q is not None and q not in DRAWABLE:
                raise ConfigError(f"{where}: unknown quantity '{q}'; known: {sorted(DRAWABLE)}")
        if spec["family"] == "curves" and not ("x" in spec and "y" in spec):
            raise ConfigError(f"{where}: a curves figure needs x and y")
        for ref in spec.get("references", []):
            if ref not in references:
                raise ConfigError(f"{where}.references: unknown reference '{ref}'; known: {sorted(references)}")
        for ref in spec.get("shrinkage_references", []):
            if ref not in shrinkage:
                raise ConfigError(f"{where}.shrinkage_references: unknown reference '{ref}'; known: {sorted(shrinkage)}")
        band = spec.get("band")
        varied = [config["studies"][s]["vary"] for s in figure_studies(spec)]
        if band is not None and (spec["family"] != "curves" or not all(band in v for v in varied)):
            raise ConfigError(f"{where}.band: '{band}' must be an axis that study '{spec['study']}' varies, in a "
                              f"curves figure (its values are the ensemble's members)")
        if spec["family"] in ("shrinkage", "modulus") and not all("dryness" in v for v in varied):
            raise ConfigError(f"{where}: a {spec['family']} figure needs studies that vary dryness")
        if not figure_cases(config, fig, expand(config)):
            raise ConfigError(f"{where}.where: selects no case of study '{spec['study']}'")
    check_compare_with(config)
    check_cases(config)


def check_labels(config, study, axis):
    """A keyless axis's value names the case its coupled keys make of base. Where base already holds a
    value's whole coupled entry (config/converged.yaml's base is resolution level 2), the base value names
    that value's case too: level-2 cells would be called level 1, and run twice. Refused."""
    spec, base = config["axes"][axis], config["base"]
    coupled, at_base = spec["coupled"], fmt(spec["base_value"])
    for value in config["studies"][study]["vary"][axis]:
        if fmt(value) == at_base:
            continue
        keys = list(coupled.get(fmt(value), {}))
        at_base_value = {k: coupled.get(at_base, {}).get(k, get_key(base, k)) for k in keys}
        if keys and all(get_key(base, k) is not None and coupled[fmt(value)][k] == at_base_value[k] for k in keys):
            raise ConfigError(
                f"axes.{axis}: base sets {', '.join(f'{k} = {at_base_value[k]}' for k in keys)}, as its value "
                f"{fmt(value)} does, so studies.{study} would run that case under two labels, {fmt(value)} and "
                f"{at_base} (its base_value): in this config, give the axis the base_value that base is and "
                f"coupled keys for the other values (as config/converged.yaml does for resolution)")


def check_compare_with(config):
    """compare_with (analysis/comparison.py): another folder than this run's, and curves figures only."""
    spec = config.get("compare_with")
    if not spec:
        return
    if pathlib.Path(spec["output_dir"]).resolve() == pathlib.Path(config["output_dir"]).resolve():
        raise ConfigError(f"compare_with.output_dir: '{spec['output_dir']}' is this run's own output_dir; name the "
                          "other run's folder")
    for fig in spec.get("figures", []):
        if fig not in config["figures"] or config["figures"][fig]["family"] != "curves":
            raise ConfigError(f"compare_with.figures: '{fig}' is not a curves figure of this config; curves figures: "
                              f"{sorted(f for f, s in config['figures'].items() if s['family'] == 'curves')}")


CASE_SCHEMA = pathlib.Path(__file__).resolve().parents[1] / "config" / "schema" / "case.schema.json"


@functools.lru_cache(maxsize=1)
def case_schema():
    """The solver's case schema (`cellsim schema`, kept in config/schema by scripts/update-docs); read
    once, and only read after."""
    return json.loads(CASE_SCHEMA.read_text())


def case_default(key):
    """The solver's default of a case key ('section.key'), from its schema."""
    section, name = key.split(".")
    return case_schema()["properties"][section]["properties"][name]["default"]


def with_defaults(case, schema):
    """The case with every key it leaves out that has a default set to that default (derived keys,
    which have none, stay out: the solver derives them)."""
    for section, spec in schema["properties"].items():
        for key, rule in spec.get("properties", {}).items():
            if "default" in rule and key not in case.get(section, {}):
                case.setdefault(section, {})[key] = rule["default"]
    return case


def check_cases(config):
    """Every case the studies make must be a valid cellsim case (ranges of the solver's schema),
    so a bad study value stops the workflow before any job runs, naming study, axis and value."""
    validator = jsonschema.Draft7Validator(case_schema())
    for case in expand(config).values():
        error = next(iter(sorted(validator.iter_errors(case.case), key=lambda e: list(e.path))), None)
        if error is not None:
            key = ".".join(str(p) for p in error.path)
            axis = next((a for a, spec in config["axes"].items() if key in axis_keys(spec)), None)
            origin = (f"studies {', '.join(case.studies)}: axis {axis}" if axis else "base or a coupled value")
            raise ConfigError(f"{origin}: case {case.name} has {key} = {error.instance!r}: {error.message}")


def _by_label(config):
    return sorted(config["axes"].items(), key=lambda item: item[1]["label"].lower())


def hides_base_value(spec):
    """An axis shows its value in case names only where it differs from base, unless it says otherwise."""
    return spec.get("hide_base_value", True)


def _named(config, values, axis, spec):
    return not (hides_base_value(spec) and _same(values[axis], base_value(config, axis)))


def _same(a, b):
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    return abs(a - b) <= 1e-12 * max(1.0, abs(b))


def case_name(config, values):
    return "_".join(spec["label"] + fmt(values[axis]) for axis, spec in _by_label(config)
                    if _named(config, values, axis, spec))


def dried_name(config, values):
    return "_".join(spec["label"] + fmt(values[axis]) for axis, spec in _by_label(config)
                    if not is_compression_only(spec) and _named(config, values, axis, spec))


def rest_name(config, values):
    return "_".join(spec["label"] + fmt(values[axis]) for axis, spec in _by_label(config)
                    if not is_compression_only(spec) and not is_drying_only(spec)
                    and _named(config, values, axis, spec)) or "base"


def build(config, values, schema=None):
    """(the cellsim case, its axis values) of these axis values over base: each axis's key set, then the
    coupled keys of every value (in the axes' order), then the schema's defaults; an axis whose key a
    coupled value set reads that value back (the closed cell's dt_ns is its 100 ns)."""
    axes = config["axes"]
    values = dict(values)
    case = copy.deepcopy(config["base"])
    for axis, value in values.items():
        if "key" in axes[axis]:
            set_key(case, axes[axis]["key"], value)
    for axis, value in values.items():
        for key, coupled in axes[axis].get("coupled", {}).get(fmt(value), {}).items():
            set_key(case, key, coupled)
    with_defaults(case, schema or case_schema())
    for axis, axis_spec in axes.items():
        if "key" in axis_spec and hides_base_value(axis_spec):
            values[axis] = get_key(case, axis_spec["key"])
    return case, values


def workflow_config(configfiles, root="."):
    """The config a workflow run on these --configfile files sees: each merged over config/config.yaml as
    Snakemake merges them (dicts key by key, anything else replaced); relative paths are under root."""
    def merged(base, update):
        out = dict(base)
        for key, value in update.items():
            out[key] = merged(out[key], value) if isinstance(value, dict) and isinstance(out.get(key), dict) else value
        return out
    root = pathlib.Path(root)
    config = yaml.safe_load((root / "config" / "config.yaml").read_text())
    for path in configfiles:
        config = merged(config, yaml.safe_load((root / path).read_text()))
    return config


def study_points(config, spec):
    """A study's points as axis values: the product of its `vary`, times its design's points if it has
    one (analysis/design.py), each with its role in the design (None without one)."""
    varied = list(spec["vary"])
    rows = [(None, {})]
    if "design" in spec:
        rows = [(role, values) for role, values in design.points(spec["design"])]
    for combo in itertools.product(*(spec["vary"][a] for a in varied)):
        for role, values in rows:
            yield role, {**dict(zip(varied, combo)), **values}


def with_design_keys(config, spec, case, values):
    """A design's keys beyond its factors: those a factor scales (`scales`), then those every point sets
    (`set`, e.g. a compression cap long enough for its slowest plates)."""
    for factor, fspec in spec["design"]["factors"].items():
        for key, power in fspec.get("scales", {}).items():
            ratio = values[factor] / base_value(config, factor)
            set_key(case, key, design.scaled(get_key(config["base"], key) or case_default(key), ratio, power))
    for key, value in spec["design"].get("set", {}).items():
        set_key(case, key, value)


def study_case(config, spec, point, base_values=None, schema=None):
    """(the cellsim case, its axis values) of one point of a study ({axis: value}, the rest at base), with its
    design's keys if it has one."""
    base_values = base_values or {axis: base_value(config, axis) for axis in config["axes"]}
    case, values = build(config, {**base_values, **point}, schema or case_schema())
    if "design" in spec:
        with_design_keys(config, spec, case, values)
    return case, values


def expand(config):
    """All cases of all studies, deduplicated: {name: Case}, in a stable order. A case named twice must be
    one run (a design's scaled or set keys could make two cases of one name differ): refused otherwise."""
    base_values = {axis: base_value(config, axis) for axis in config["axes"]}
    schema = case_schema()
    cases = {}
    for study, spec in config["studies"].items():
        for _role, point in study_points(config, spec):
            case, values = study_case(config, spec, point, base_values, schema)
            name = case_name(config, values)
            if name not in cases:
                cases[name] = Case(name, dried_name(config, values), rest_name(config, values), values, case)
            elif cases[name].case != case:
                raise ConfigError(f"studies.{study}: case {name} is also another study's, with different keys "
                                  f"(a design's scales or set): give one of them an axis value that tells them apart")
            if study not in cases[name].studies:
                cases[name].studies.append(study)
    return cases


def design_roles(config, study):
    """{case name: role} of a design study's cases: 'train', 'held_out' or 'check' (analysis/design.py)."""
    spec, base_values = config["studies"][study], {axis: base_value(config, axis) for axis in config["axes"]}
    return {case_name(config, build(config, {**base_values, **point})[1]): role
            for role, point in study_points(config, spec)}


def dried_states(cases):
    """{dried name: case dict for drying}: one per distinct drying, whatever compressions follow."""
    out = {}
    for case in cases.values():
        out.setdefault(case.dried, case.case)
    return out


def rest_states(cases):
    """{rest name: case dict of the settle run}: one per distinct cell at rest, whatever dryness follows.
    Cases that share a name must share the run (a name lists every axis that shapes it)."""
    out = {}
    for case in cases.values():
        rest = rest_case(case.case)
        if out.setdefault(case.rest, rest) != rest:
            raise ConfigError(f"cases share the state at rest {case.rest!r} but settle differently "
                              f"(e.g. {case.name}): give the axis that tells them apart a label")
    return out


def matches(values, where):
    for axis, wanted in (where or {}).items():
        allowed = wanted if isinstance(wanted, list) else [wanted]
        if not any(_same(values[axis], w) for w in allowed):
            return False
    return True


def figure_cases(config, fig, cases):
    """Names of the cases a figure draws: its study's cases that match its `where`."""
    spec = config["figures"][fig]
    studies = set(figure_studies(spec))
    return [c.name for c in cases.values() if studies & set(c.studies) and matches(c.values, spec.get("where"))]


def case_json(case):
    return json.dumps(case, indent=2, sort_keys=True) + "\n"
