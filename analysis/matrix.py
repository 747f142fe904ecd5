"""The experiment matrix: studies in config -> cases with readable, stable names.

A case is `base` with the values of every axis set; its name lists every axis as label+value,
in the order of the labels (e.g. D150_G18_P200_t6_v1_X0.5), so names are stable when studies are
added or removed, whatever order config files list the axes in, and identical cases of different
studies coincide. The dried state of a case is the same name
without the axes that only touch the compression stage.
"""
import copy
import itertools
import json
import pathlib
from dataclasses import dataclass, field


class ConfigError(ValueError):
    """A config that passes the schema but is inconsistent (names the key)."""


@dataclass
class Case:
    name: str
    dried: str
    values: dict                     # axis -> value
    case: dict                       # the full cellsim case (nested, file units)
    studies: list = field(default_factory=list)


def fmt(value):
    """A number as it appears in names: 1.0 -> 1, 0.18 -> 0.18, 2.5e-6 -> 2.5e-06."""
    return f"{value:g}"


def get_key(case, key):
    section, name = key.split(".", 1)
    return case.get(section, {}).get(name)


def set_key(case, key, value):
    section, name = key.split(".", 1)
    case.setdefault(section, {})[name] = value


def is_compression_only(key):
    return key.startswith("compression.")


def check(config, root="."):
    """Cross-references the schema cannot check; raises ConfigError naming the key."""
    axes, studies = config["axes"], config["studies"]
    for axis, spec in axes.items():
        if get_key(config["base"], spec["key"]) is None:
            raise ConfigError(f"axes.{axis}: base has no value for its key '{spec['key']}' (add it to base)")
    labels = [spec["label"] for spec in axes.values()]
    if len(set(labels)) != len(labels):
        raise ConfigError(f"axes: labels must be distinct, got {labels}")
    for study, spec in studies.items():
        for axis in spec["vary"]:
            if axis not in axes:
                raise ConfigError(f"studies.{study}.vary.{axis}: unknown axis; known: {sorted(axes)}")
    references = config.get("references", {})
    for ref, spec in references.items():
        if not (pathlib.Path(root) / spec["file"]).is_file():
            raise ConfigError(f"references.{ref}.file: no such file '{spec['file']}'")
    from analysis.quantities import DRAWABLE  # the solver's time series and those derived from them
    for fig, spec in config["figures"].items():
        where = f"figures.{fig}"
        if spec["study"] not in studies:
            raise ConfigError(f"{where}.study: unknown study '{spec['study']}'; known: {sorted(studies)}")
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
        for q in [spec.get("x")] + spec.get("y", []):
            if q is not None and q not in DRAWABLE:
                raise ConfigError(f"{where}: unknown quantity '{q}'; known: {sorted(DRAWABLE)}")
        if spec["family"] == "curves" and not ("x" in spec and "y" in spec):
            raise ConfigError(f"{where}: a curves figure needs x and y")
        for ref in spec.get("references", []):
            if ref not in references:
                raise ConfigError(f"{where}.references: unknown reference '{ref}'; known: {sorted(references)}")
        if not figure_cases(config, fig, expand(config)):
            raise ConfigError(f"{where}.where: selects no case of study '{spec['study']}'")
    check_cases(config, root)


def check_cases(config, root="."):
    """Every case the studies make must be a valid cellsim case (ranges of the solver's schema),
    so a bad study value stops the workflow before any job runs, naming study, axis and value."""
    import jsonschema
    schema = json.loads((pathlib.Path(root) / "config" / "schema" / "case.schema.json").read_text())
    validator = jsonschema.Draft7Validator(schema)
    for case in expand(config).values():
        error = next(iter(sorted(validator.iter_errors(case.case), key=lambda e: list(e.path))), None)
        if error is not None:
            key = ".".join(str(p) for p in error.path)
            axis = next((a for a, spec in config["axes"].items() if spec["key"] == key), None)
            origin = (f"studies {', '.join(case.studies)}: axis {axis}" if axis else "base or a coupled value")
            raise ConfigError(f"{origin}: case {case.name} has {key} = {error.instance!r}: {error.message}")


def _by_label(config):
    return sorted(config["axes"].items(), key=lambda item: item[1]["label"].lower())


def case_name(config, values):
    return "_".join(spec["label"] + fmt(values[axis]) for axis, spec in _by_label(config))


def dried_name(config, values):
    return "_".join(spec["label"] + fmt(values[axis]) for axis, spec in _by_label(config)
                    if not is_compression_only(spec["key"]))


def expand(config):
    """All cases of all studies, deduplicated: {name: Case}, in a stable order."""
    axes, base = config["axes"], config["base"]
    base_values = {axis: get_key(base, spec["key"]) for axis, spec in axes.items()}
    cases = {}
    for study, spec in config["studies"].items():
        varied = list(spec["vary"])
        for combo in itertools.product(*(spec["vary"][a] for a in varied)):
            values = dict(base_values)
            values.update(dict(zip(varied, combo)))
            name = case_name(config, values)
            if name not in cases:
                case = copy.deepcopy(base)
                for axis, value in values.items():
                    set_key(case, axes[axis]["key"], value)
                    for key, coupled in axes[axis].get("coupled", {}).get(fmt(value), {}).items():
                        set_key(case, key, coupled)
                cases[name] = Case(name, dried_name(config, values), values, case)
            if study not in cases[name].studies:
                cases[name].studies.append(study)
    return cases


def dried_states(cases):
    """{dried name: case dict for drying}: one per distinct drying, whatever compressions follow."""
    out = {}
    for case in cases.values():
        out.setdefault(case.dried, case.case)
    return out


def matches(values, where):
    for axis, wanted in (where or {}).items():
        allowed = wanted if isinstance(wanted, list) else [wanted]
        if not any(abs(values[axis] - w) <= 1e-12 * max(1.0, abs(w)) for w in allowed):
            return False
    return True


def figure_cases(config, fig, cases):
    """Names of the cases a figure draws: its study's cases that match its `where`."""
    spec = config["figures"][fig]
    return [c.name for c in cases.values() if spec["study"] in c.studies and matches(c.values, spec.get("where"))]


def case_json(case):
    return json.dumps(case, indent=2, sort_keys=True) + "\n"
