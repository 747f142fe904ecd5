"""Mutations of valid case files and --set overrides, the way people get them wrong: keys dropped,
duplicated, renamed, nested wrong; numbers at 0, negative, huge, tiny, non-finite; floats for counts,
strings for numbers, very long strings; sections of the wrong type; and values each valid alone that
contradict each other. A mutant is what one solver command gets: the case file's text and the --set
arguments, with the operations that made it (seeded: the same seed gives the same mutants)."""
import copy
import json
from dataclasses import dataclass, field

# Small valid cases that run a few dozen steps in seconds under the sanitizers: every mutation starts
# from one of them, so a mutant that is still valid runs every code path it reaches.
_SMALL = {"cell": {"n_wall": 162, "n_fluid": 100}, "settle": {"max_iterations": 40},
          "drying": {"steps": 40}, "compression": {"steps": 40, "plate_speed_m_s": 10},
          "output": {"record_every": 10, "snapshot_every": 20, "progress_interval_s": 0}}


def _with(base, **sections):
    case = copy.deepcopy(base)
    for name, keys in sections.items():
        case.setdefault(name, {}).update(keys)
    return case


SEEDS = {
    "cell": _SMALL,
    "cell_pressure": _with(_SMALL, coupling={"model": "pressure"}),
    "cell_to_strain": _with(_SMALL, compression={"end_strain": 0.002, "plate_speed_m_s": 50}),
    "cell_unload": _with(_SMALL, compression={"unload_at_strain": 0.001, "end_strain": 0.01, "plate_speed_m_s": 50}),
    "cell_plastic_mixed": _with(_SMALL, wall={"yield_stress_MPa": 40, "hardening_MPa": 5},
                                heterogeneity={"wall_G_cv": 0.2, "correlation_length_um": 20, "fluid_viscosity_cv": 0.1}),
    "pair": _with(_SMALL, tissue={"cells_x": 2}, compression={"plate_length_um": 400, "plate_width_um": 400}),
    "slab": _with(_SMALL, tissue={"cells_x": 2, "cells_y": 2, "lateral": "periodic", "packing": "close"},
                  compression={"lateral": "unconfined"}),
}

# Values that break a number: each a JSON text, spliced into the file as is (so 1e999 and NaN reach the
# parser as a user would type them).
BAD_NUMBERS = ["0", "-0", "-1", "-150", "1e308", "1e999", "-1e999", "1e-300", "5e-324", "NaN", "Infinity",
               "-Infinity", "nan", "inf", '"200"', '"nan"', '""', "true", "false", "null", "[]", "[1]", "{}",
               '{"value": 1}', "0.5", "3.5", "1e6", "1e9", "2147483648", "9223372036854775808",
               "1" + "0" * 400, "0x10", "1.", ".5", "+1", "01", "1e", '"' + "9" * 5000 + '"']
# Values a --set argument is given as text (apply_override parses them).
BAD_OVERRIDE_TEXTS = ["", " ", "0", "-1", "1e400", "-1e400", "1e-400", "nan", "NaN", "inf", "-Infinity", "0x10",
                      "1,5", "1 5", " 5", "5 ", "true", "null", "[1]", "{}", '"5"', '"pressure"', "pressure",
                      "1" + "0" * 400, "9" * 30, "3.5", "\u00e9", "a" * 10000,
                      "\udcff"]  # the last: the byte 0xff, not UTF-8 (os.fsencode's surrogate escape)
LONG = "x" * 100_000


@dataclass
class Mutant:
    seed: str
    ops: list = field(default_factory=list)
    text: str = ""
    overrides: list = field(default_factory=list)

    def as_record(self):
        return {"seed": self.seed, "ops": self.ops, "text": self.text, "overrides": self.overrides}


def _leaves(case):
    return [(s, k) for s, body in case.items() if isinstance(body, dict) for k in body]


def _known_keys(schema_keys):
    return [tuple(k.split(".", 1)) for k in schema_keys]


class CaseMutator:
    """Draws mutants from SEEDS with rng; schema_keys: every section.key the solver knows (its
    `cellsim params`), so that mutations also reach keys the seeds leave at their defaults."""

    def __init__(self, rng, schema_keys):
        self.rng = rng
        self.keys = _known_keys(schema_keys)

    def mutant(self):
        rng = self.rng
        seed = rng.choice(sorted(SEEDS))
        case = copy.deepcopy(SEEDS[seed])
        m = Mutant(seed)
        splices = []  # (section, key, raw JSON text) written into the text after json.dumps
        for _ in range(rng.choice([1, 1, 1, 2, 2, 3])):
            op = rng.choice(self._structural + self._valued + self._contradictions + self._overriding)
            op(self, case, m, splices)
        m.text = self._render(case, splices, m)
        return m

    # --- structural: keys and sections
    def _drop(self, case, m, splices):
        leaves = _leaves(case)
        if leaves and self.rng.random() < 0.8:
            s, k = self.rng.choice(leaves)
            del case[s][k]
            m.ops.append(f"drop {s}.{k}")
        elif case:
            s = self.rng.choice(sorted(case))
            del case[s]
            m.ops.append(f"drop section {s}")

    def _rename(self, case, m, splices):
        leaves = _leaves(case)
        if not leaves:
            return
        s, k = self.rng.choice(leaves)
        value = case[s].pop(k)
        how = self.rng.choice(["typo", "case", "section", "unit", "space"])
        if how == "typo":
            i = self.rng.randrange(len(k))
            k2 = k[:i] + k[i + 1:] if len(k) > 1 else k + "x"
            case[s][k2] = value
        elif how == "case":
            case[s][k.upper()] = value
        elif how == "unit":
            case[s][k.split("_")[0]] = value
        elif how == "space":
            case[s][k + " "] = value
        else:
            other = self.rng.choice([x for x in {a for a, _ in self.keys} if x != s] or [s])
            case.setdefault(other, {})
            if isinstance(case[other], dict):
                case[other][k] = value
        m.ops.append(f"rename {s}.{k} ({how})")

    def _nest_wrong(self, case, m, splices):
        s, k = self.rng.choice(self.keys)
        how = self.rng.choice(["flat", "deep", "top"])
        value = 1
        if how == "flat":  # "cell.n_wall": 1 at the top, or inside its section
            case[f"{s}.{k}"] = value
        elif how == "deep":
            case.setdefault(s, {})
            if isinstance(case[s], dict):
                case[s][k] = {k: value}
        else:
            case[k] = value
        m.ops.append(f"nest {s}.{k} ({how})")

    def _section_type(self, case, m, splices):
        s = self.rng.choice(sorted({a for a, _ in self.keys} | {"description"}))
        raw = self.rng.choice(["5", "[]", '"cell"', "null", "true", "[{}]", '"' + LONG + '"'])
        splices.append((s, None, raw))
        m.ops.append(f"section {s} = {raw[:20]}")

    def _duplicate(self, case, m, splices):
        leaves = _leaves(case)
        if not leaves:
            return
        s, k = self.rng.choice(leaves)
        splices.append((s, k, "DUPLICATE"))
        m.ops.append(f"duplicate {s}.{k}")

    def _whole_file(self, case, m, splices):
        how = self.rng.choice(["truncate", "garbage", "array", "bom", "deep", "empty", "nul", "latin1", "bytes"])
        splices.append((None, None, how))
        m.ops.append(f"file {how}")

    # --- values
    def _bad_value(self, case, m, splices):
        s, k = self.rng.choice(self.keys)
        raw = self.rng.choice(BAD_NUMBERS)
        splices.append((s, k, raw))
        m.ops.append(f"{s}.{k} = {raw[:20]}")

    def _scaled_value(self, case, m, splices):
        leaves = [(s, k) for s, k in _leaves(case) if isinstance(case[s][k], (int, float))
                  and not isinstance(case[s][k], bool)]
        if not leaves:
            return
        s, k = self.rng.choice(leaves)
        factor = self.rng.choice([1e-9, 1e-3, 0.1, 0.5, 2, 10, 1e3, 1e9, -1])
        case[s][k] = case[s][k] * factor
        m.ops.append(f"{s}.{k} x {factor}")

    def _long_string(self, case, m, splices):
        s, k = self.rng.choice(self.keys + [("description", None)])
        if k is None:
            case["description"] = LONG
        else:
            case.setdefault(s, {})
            if isinstance(case[s], dict):
                case[s][k] = LONG
        m.ops.append(f"{s}.{k} = long string")

    # --- combinations each valid alone
    def _contradiction(self, case, m, splices):
        rng = self.rng
        choices = {
            "unload past end": {"compression": {"unload_at_strain": 0.3, "end_strain": 0.2}},
            "cap before end_strain": {"compression": {"steps": 5, "end_strain": 0.5}},
            "cap before unload turn": {"compression": {"steps": 5, "unload_at_strain": 0.3}},
            "period smaller than cells": {"tissue": {"cells_x": 2, "cells_y": 2, "lateral": "periodic",
                                                     "centre_distance_over_diameter": 0.6}},
            "drying inverts wall": {"drying": {"dryness": 1e-6}, "wall": {"contraction_ratio": 0.999999}},
            "h0 and h_over_dx": {"fluid": {"h0_um": 8, "h_over_dx": 1.2}},
            "unconfined cell": {"compression": {"lateral": "unconfined"}},
            "gap larger than cell": {"cell": {"fill_gap_um": 74.9}},
            "wall gap huge": {"tissue": {"cells_x": 2, "wall_gap_um": 500}},
            "dt at the limit": {"time": {"dt_ns": 1e-6}},
            "tiny dt derived caps": {"time": {"dt_ns": 1e-300}, "drying": {"steps": None}, "compression": {"steps": None}},
            "huge tissue": {"tissue": {"cells_x": 20, "cells_y": 20, "cells_z": 20}, "cell": {"n_wall": 200000}},
            "huge cells": {"cell": {"n_fluid": 1000000}, "tissue": {"cells_x": 20}},
            "tiny cell many particles": {"cell": {"diameter_um": 1, "n_fluid": 5000}},
            "huge cell few particles": {"cell": {"diameter_um": 10000, "n_fluid": 10, "n_wall": 12}},
            "zero turgor dry": {"cell": {"turgor_kPa": 0}, "drying": {"dryness": 0.1}},
            "slow plate cap": {"compression": {"plate_speed_m_s": 1e-9, "steps": None}},
            "no output records": {"output": {"record_every": 1000000000}},
            "plastic below turgor": {"wall": {"yield_stress_MPa": 1e-6}},
            "spread with cubic": {"tissue": {"cells_x": 2, "diameter_spread": 0.3, "packing": "cubic"}},
            "period viscosity tiny": {"tissue": {"cells_x": 2, "cells_y": 2, "lateral": "periodic",
                                                 "period_viscosity_Pa_s": 1e-9}},
        }
        name = rng.choice(sorted(choices))
        for s, keys in choices[name].items():
            if not isinstance(case.get(s), dict):
                case[s] = {}
            case[s].update(keys)
        m.ops.append(f"contradiction: {name}")

    # --- --set
    def _override(self, case, m, splices):
        rng = self.rng
        s, k = rng.choice(self.keys)
        how = rng.choice(["value", "value", "key", "form"])
        if how == "value":
            m.overrides.append(f"{s}.{k}={rng.choice(BAD_OVERRIDE_TEXTS)}")
        elif how == "key":
            m.overrides.append(rng.choice([f"{s}={1}", f"{s}.{k}.x=1", f"{k}=1", f".{k}=1", f"{s}.=1",
                                           f"{s}.{k[:-1]}=1", f"{s.upper()}.{k}=1", f"{s}..{k}=1"]))
        else:
            m.overrides.append(rng.choice([f"{s}.{k}", f"={k}", "=", f"{s}.{k}==1", f"{s}.{k}= 1", "",
                                           f"{s}.{k}=1=2"]))
        m.ops.append(f"--set {m.overrides[-1][:40]!r}")

    _structural = [_drop, _rename, _nest_wrong, _section_type, _duplicate, _whole_file]
    _valued = [_bad_value, _bad_value, _scaled_value, _scaled_value, _long_string]
    _contradictions = [_contradiction, _contradiction]
    _overriding = [_override]

    # --- the file's text
    def _render(self, case, splices, m):
        marker = "\u0001SPLICE{}\u0001"
        wholes = [raw for s, k, raw in splices if s is None]
        for i, (s, k, raw) in enumerate(splices):
            if s is None:
                continue
            if k is None:
                case[s] = marker.format(i)
            elif raw == "DUPLICATE":
                pass
            else:
                if not isinstance(case.get(s), dict):
                    case[s] = {}
                case[s][k] = marker.format(i)
        text = json.dumps(case, indent=1, ensure_ascii=False)
        for i, (s, k, raw) in enumerate(splices):
            if s is None:
                continue
            if raw == "DUPLICATE":
                if isinstance(case.get(s), dict) and k in case[s]:
                    key = json.dumps(k)
                    at = text.find(f"{key}:", text.find(json.dumps(s) + ":"))
                    if at >= 0:
                        dup = "99" if self.rng.random() < 0.5 else json.dumps(case[s][k])
                        text = text[:at] + f"{key}: {dup}, " + text[at:]
                continue
            text = text.replace(json.dumps(marker.format(i), ensure_ascii=False), raw)
        for how in wholes:
            text = _whole_file_text(text, how, self.rng)
        return text


def _whole_file_text(text, how, rng):
    if how == "truncate":
        return text[: rng.randrange(len(text))]
    if how == "garbage":
        return "".join(chr(rng.randrange(1, 0x250)) for _ in range(rng.randrange(1, 200)))
    if how == "array":
        return f"[{text}]"
    if how == "bom":
        return "\ufeff" + text
    if how == "deep":
        depth = rng.choice([1000, 100_000])
        return "[" * depth + "]" * depth if rng.random() < 0.5 else '{"a":' * depth + "1" + "}" * depth
    if how == "empty":
        return rng.choice(["", " ", "\n", "{}", "null", "0"])
    if how == "nul":
        at = rng.randrange(len(text) + 1)
        return text[:at] + "\0" + text[at:]
    if how == "latin1":
        return text.replace('"cell"', '"c\u00e9ll"', 1)
    if how == "bytes":  # a byte that is not UTF-8 inside a string (written with surrogateescape)
        return text.replace('"cell"', '"c\udce9ll"', 1)
    raise ValueError(how)
