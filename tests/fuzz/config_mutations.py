"""Mutations of the workflow's config (config/ci.yaml merged over config/config.yaml) through
`snakemake -n`: each mutant is ci.yaml with one to three entries of the merged config changed: a value
of the wrong type, out of range, empty or null (a key 'dropped': Snakemake merges a --configfile over
config.yaml, so null is how a file takes a key away), an unknown key, a list where a mapping goes, a
study that names an axis, a figure or a reference that does not exist. Every one must be planned or
refused with a message that names the key (rules: refused_names_the_key)."""
import copy
import re
import subprocess
import time
from dataclasses import dataclass, field

import yaml

SNAKEMAKE_LIMIT_S = 120
ODD_VALUES = [None, 0, -1, 1e308, "", "x", "nan", [], {}, [None], {"x": 1}, True, 3.5, "../../etc", "a b",
              "fig01", "D_um", 10 ** 20, -0.0, "\u00e9", "x" * 5000]


@dataclass
class ConfigMutant:
    seed: str = "config/ci.yaml"
    ops: list = field(default_factory=list)
    text: str = ""
    overrides: list = field(default_factory=list)  # unused: the config is the file
    paths: list = field(default_factory=list)       # the mutated entries, as key paths

    def as_record(self):
        return {"seed": self.seed, "ops": self.ops, "text": self.text, "paths": self.paths}


def _merged(base, update):
    out = dict(base)
    for key, value in update.items():
        out[key] = _merged(out[key], value) if isinstance(value, dict) and isinstance(out.get(key), dict) else value
    return out


def _paths(node, prefix=()):
    """Every key path of the config's mappings (lists are entered by index)."""
    items = node.items() if isinstance(node, dict) else enumerate(node) if isinstance(node, list) else []
    for key, value in items:
        yield prefix + (key,)
        yield from _paths(value, prefix + (key,))


def _override(path, value):
    """The smallest mapping that, merged over the config, sets `path` to value (a list index: the whole
    list, mutated, under its key)."""
    out = value
    for key in reversed(path):
        out = {key: out}
    return out


class ConfigMutator:
    def __init__(self, rng, root):
        self.rng = rng
        base = yaml.safe_load((root / "config" / "config.yaml").read_text())
        self.ci = yaml.safe_load((root / "config" / "ci.yaml").read_text())
        self.config = _merged(base, self.ci)
        self.paths = [p for p in _paths(self.config) if p[0] != "output_dir"]

    def mutant(self):
        m = ConfigMutant()
        mutated = copy.deepcopy(self.ci)
        for _ in range(self.rng.choice([1, 1, 2, 3])):
            path, value, what = self._one()
            # A path through a list: the list itself, with the element changed, is what the file sets.
            cut = next((i for i, k in enumerate(path) if isinstance(k, int)), len(path))
            head, tail = path[:cut], path[cut:]
            if tail:
                container = copy.deepcopy(self._get(head))
                target = container
                for k in tail[:-1]:
                    target = target[k]
                target[tail[-1]] = value
                value = container
            mutated = _merged(mutated, _override(head, value))
            m.ops.append(what)
            m.paths.append([str(k) for k in path])
        m.text = yaml.safe_dump(mutated, sort_keys=False, allow_unicode=True)
        return m

    def _get(self, path):
        node = self.config
        for k in path:
            node = node[k]
        return node

    def _one(self):
        return self._semantic() if self.rng.random() < 0.5 else self._typed()

    def _semantic(self):
        """A change of the right type that the schema lets through and the matrix check must judge: a
        study's axis given values out of the case's range, a figure pointed at another study, axis,
        quantity or moment, an axis pointed at another key."""
        rng, c = self.rng, self.config
        study = rng.choice(sorted(c["studies"]))
        figure = rng.choice(sorted(c["figures"]))
        axis = rng.choice(sorted(c["axes"]))
        numbers = [0, -1, 1.5, 1e-9, 1e9, 0.5, 2, 100, 12345.678]
        choices = [
            (("studies", study, "vary", rng.choice(sorted(c["studies"][study]["vary"]))), [rng.choice(numbers)]),
            (("studies", study, "vary", axis), [rng.choice(numbers), rng.choice(numbers)]),
            (("studies", study, "target"), rng.choice(["convergence", "tissue", "extensions"])),
            (("figures", figure, "study"), rng.choice(sorted(c["studies"]) + ["nonesuch"])),
            (("figures", figure, "where"), {axis: rng.choice(numbers)}),
            (("figures", figure, "x"), rng.choice(["time_s", "strain", "stres", "plate_stress_Pa", "dryness"])),
            (("figures", figure, "y"), [rng.choice(["area_m2", "volum_m3", "plate_stress_Pa", "x"])]),
            (("figures", figure, "cols"), rng.choice(sorted(c["axes"]) + ["moment", "nonesuch"])),
            (("figures", figure, "rows"), rng.choice(sorted(c["axes"]) + ["moment", "nonesuch"])),
            (("figures", figure, "moments"), [rng.choice(["end", "start", "compression_9", "end_of_drying", "x"])]),
            (("axes", axis, "key"), rng.choice(["cell.diameter_um", "wall.G_MPa", "cell.nonesuch", "tissue.cells_x"])),
            (("base", "drying", "dryness"), rng.choice(numbers)),
            (("base", "cell", "n_wall"), rng.choice([0, 1, 12, 200001])),
        ]
        path, value = rng.choice(choices)
        return path, value, f"{'.'.join(map(str, path))} = {str(value)[:30]!r}"

    def _typed(self):
        rng = self.rng
        path = rng.choice(self.paths)
        old = self._get(path)
        how = rng.choice(["odd", "odd", "odd", "unknown key", "scale", "wrong name", "list for map"])
        if how == "unknown key" and isinstance(old, dict):
            name = rng.choice(["colour", "G_Mpa", "vary ", "Studies", "x.y", "1"])
            return path + (name,), rng.choice(ODD_VALUES[:8]), f"{'.'.join(map(str, path))}.{name} added"
        if how == "scale" and isinstance(old, (int, float)) and not isinstance(old, bool):
            factor = rng.choice([-1, 0, 1e-9, 1e9, 0.5])
            return path, old * factor, f"{'.'.join(map(str, path))} x {factor}"
        if how == "wrong name" and isinstance(old, str):
            return path, old[:-1] + "Z" if old else "Z", f"{'.'.join(map(str, path))} misnamed"
        if how == "list for map" and isinstance(old, dict):
            return path, list(old.values())[:2], f"{'.'.join(map(str, path))} a list"
        value = rng.choice(ODD_VALUES)
        return path, value, f"{'.'.join(map(str, path))} = {str(value)[:20]!r}"


def check_mutant(root, mutant, folder):
    """snakemake -n on the mutant; returns (exit code, broken rules)."""
    folder.mkdir(parents=True, exist_ok=True)
    config = folder / "mutant.yaml"
    config.write_text(mutant.text)
    t0 = time.monotonic()
    try:
        done = subprocess.run(["snakemake", "-n", "--nolock", "--cores", "2", "--configfile", str(config),
                               "--config", f"output_dir={folder / 'out'}"], cwd=root, capture_output=True,
                              text=True, timeout=SNAKEMAKE_LIMIT_S)
    except subprocess.TimeoutExpired:
        return None, [f"snakemake -n did not end within {SNAKEMAKE_LIMIT_S} s"]
    seconds = time.monotonic() - t0
    output = done.stdout + done.stderr
    if done.returncode == 0:
        broken = [] if "This was a dry-run" in output or "Nothing to be done" in output else ["exit 0 without a plan"]
        if (folder / "out").exists() and any((folder / "out").rglob("*.h5")):
            broken.append("a dry run wrote results")
        return 0, broken
    return done.returncode, refused_names_the_key(output, mutant.paths, seconds)


# Python errors that mean the workflow's own code broke on the config, not that a check refused it.
_CRASH = re.compile(r"\b(TypeError|KeyError|AttributeError|IndexError|ValueError|ZeroDivisionError|"
                    r"RecursionError|UnboundLocalError|NameError|AssertionError)\b")


def refused_names_the_key(output, paths, seconds):
    broken = []
    names = {k for path in paths for k in path if not k.isdigit()}
    # jsonschema names a key as instance['a']['b'] or in its message; our checks as a.b.c
    if not any(name in output for name in names):
        broken.append(f"refusal names none of {sorted(names)}: {output.strip()[-300:]!r}")
    crash = _CRASH.search(output)
    if crash and "WorkflowError" not in output and "ValidationError" not in output and "config:" not in output:
        broken.append(f"a {crash.group(1)} instead of a refusal: {output.strip()[-400:]!r}")
    return broken
