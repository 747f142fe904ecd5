"""Corrupted inputs to --from: valid result files (a cell at rest, a dried cell, a dried periodic slab)
truncated, bit-flipped, zeroed, grown, or edited into files that open but are wrong (a dataset or an
attribute taken away, of another shape or type), and the leftovers of an interrupted run (a .partial,
a file marked incomplete, an empty file, a folder). Rules: exit 2 or 4 with a message naming the file,
or, where the change left what the solver reads intact (a flip in unused bytes), exit 0 with the very
result the intact file gives; never a crash, a hang or a silent use."""
import hashlib
import json
import random
import shutil
from dataclasses import dataclass, field

import h5py
import numpy as np

from tests.fuzz import rules, solver_cases
from tests.fuzz.case_mutations import SEEDS

SOURCES = {  # name: (case keys over the small cell, drying steps: 0 = a cell at rest)
    "rest": ({}, 0),
    "dried": ({"drying": {"dryness": 0.5}}, 40),
    "slab": ({"tissue": {"cells_x": 2, "cells_y": 2, "lateral": "periodic"}}, 40),
}


@dataclass
class FileMutant:
    seed: str
    ops: list = field(default_factory=list)
    text: str = ""  # unused: the mutant is a file, made again from seed and ops
    overrides: list = field(default_factory=list)
    salt: int = 0

    def as_record(self):
        return {"seed": self.seed, "ops": self.ops, "salt": self.salt}


def _case(source):
    keys, drying_steps = SOURCES[source]
    case = json.loads(json.dumps(SEEDS["cell"]))  # a copy
    for section, body in keys.items():
        case.setdefault(section, {}).update(body)
    case["drying"]["steps"] = drying_steps
    case["compression"]["steps"] = 0
    return case


def _digest(path):
    """What a compression continued from a file gave: its final state and time series, hashed."""
    with h5py.File(path, "r") as f:
        h = hashlib.sha256()
        for group in ("state", "timeseries"):
            for name in sorted(f[group]):
                h.update(name.encode() + np.ascontiguousarray(f[group][name][()]).tobytes())
        return h.hexdigest()


class Corrupter:
    def __init__(self, rng, cellsim, folder):
        self.rng, self.cellsim, self.folder = rng, cellsim, folder
        folder.mkdir(parents=True, exist_ok=True)
        self.clean = {}  # source -> (state file, case file, digest of its clean continuation)
        for source in SOURCES:
            case = folder / f"{source}.json"
            solver_cases.write_case(case, json.dumps(_case(source)))
            state = folder / f"{source}.h5"
            o = solver_cases.execute([cellsim, "run", case, "-o", state, "--quiet"], solver_cases.RUN_LIMIT_S)
            assert o.returncode == 0, o.stderr
            compress = folder / f"{source}.compress.json"
            compressed = json.loads(case.read_text())
            compressed["compression"]["steps"] = 20
            if SOURCES[source][1] == 0:  # a cell at rest continues into its drying
                compressed["drying"]["steps"] = 20
            solver_cases.write_case(compress, json.dumps(compressed))
            out = folder / f"{source}.out.h5"
            o = solver_cases.execute([cellsim, "run", compress, "--from", state, "-o", out, "--quiet"],
                                     solver_cases.RUN_LIMIT_S)
            assert o.returncode == 0, o.stderr
            self.clean[source] = (state, compress, _digest(out))

    def mutant(self):
        m = FileMutant(self.rng.choice(sorted(SOURCES)), salt=self.rng.randrange(2 ** 31))
        size = self.clean[m.seed][0].stat().st_size
        rng = self.rng
        how = rng.choice(["flip", "flip", "flip", "flip metadata", "truncate", "zero", "append", "edit", "leftover"])
        if how == "flip":
            m.ops = [("flip", rng.randrange(size * 8)) for _ in range(rng.choice([1, 1, 2, 8]))]
        elif how == "flip metadata":  # the superblock and the first object headers
            m.ops = [("flip", rng.randrange(min(size, 4096) * 8))]
        elif how == "truncate":
            m.ops = [("truncate", rng.randrange(size))]
        elif how == "zero":
            at = rng.randrange(size)
            m.ops = [("zero", at, rng.choice([8, 64, 512, 4096]))]
        elif how == "append":
            m.ops = [("append", rng.choice([1, 100, 10000]))]
        elif how == "edit":
            m.ops = [("edit", rng.choice(["drop dataset", "drop attribute", "reshape", "retype", "nan", "shrink"]),
                      rng.randrange(10 ** 6))]
        else:
            m.ops = [("leftover", rng.choice(["partial", "incomplete", "empty", "folder", "text"]))]
        return m

    def make(self, m, path):
        state = self.clean[m.seed][0]
        if m.ops[0][0] == "leftover":
            kind = m.ops[0][1]
            if kind == "folder":
                path.mkdir()
            elif kind == "empty":
                path.write_bytes(b"")
            elif kind == "text":
                path.write_text("not an HDF5 file\n")
            else:
                shutil.copy(state, path)
                with h5py.File(path, "r+") as f:
                    f.attrs["completed"] = 0
                if kind == "partial":
                    path.rename(path.with_name(path.name + ".partial"))
                    return path.with_name(path.name + ".partial")
            return path
        shutil.copy(state, path)
        if m.ops[0][0] == "edit":
            _edit(path, m.ops[0][1], random.Random(m.ops[0][2]))
            return path
        data = bytearray(path.read_bytes())
        bits = len(data) * 8  # offsets past the end (a file of a format since grown smaller) wrap around
        for op in m.ops:
            if op[0] == "flip":
                data[op[1] % bits // 8] ^= 1 << (op[1] % 8)
            elif op[0] == "truncate":
                del data[op[1] % len(data):]
            elif op[0] == "zero":
                at = op[1] % len(data)
                data[at:at + op[2]] = bytes(len(data[at:at + op[2]]))
            elif op[0] == "append":
                data += bytes(random.Random(op[1]).randrange(256) for _ in range(op[1]))
        path.write_bytes(bytes(data))
        return path

    def check(self, m, folder):
        folder.mkdir(parents=True, exist_ok=True)
        given = self.make(m, folder / "state.h5")
        _, case, clean_digest = self.clean[m.seed]
        out = folder / "out.h5"
        o = solver_cases.execute([self.cellsim, "run", case, "--from", given, "-o", out, "--quiet"],
                                 solver_cases.RUN_LIMIT_S, out=out, whole_stacks=True)
        broken = rules.judge_run(o, solver_cases.result_attributes)
        if o.returncode == 3:
            broken.append("a corrupted state ran into a numerical failure instead of being refused")
        # A file without one of the attributes added over the versions (the plates', the energy account's,
        # the period's) reads as one written before it, by design: continued from, with that attribute's
        # old default; only changed bytes must never be used.
        older_file = m.ops[0][:2] == ("edit", "drop attribute")
        if o.returncode == 0 and out.exists() and _digest(out) != clean_digest and not older_file:
            broken.append("silent use: the corrupted file gave another result than the intact one")
        if o.returncode in (2, 4) and str(given) not in o.stderr and given.name not in o.stderr:
            broken.append(f"refusal does not name the file: {o.stderr.strip()[-200:]!r}")
        return o.returncode, broken


def _edit(path, what, rng):
    with h5py.File(path, "r+") as f:
        state = f["state"]
        names = sorted(state)
        if what == "drop dataset":
            del state[rng.choice(names)]
        elif what == "drop attribute":
            holder = rng.choice([f, state])
            del holder.attrs[rng.choice(sorted(holder.attrs))]
        elif what in ("reshape", "shrink", "nan", "retype"):
            name = rng.choice(names)
            data = state[name][()]
            del state[name]
            if what == "reshape":
                data = data.reshape(-1)
            elif what == "shrink":
                data = data[: max(0, len(data) - 1)]
            elif what == "nan" and data.dtype.kind == "f" and data.size:
                data = data.copy()
                data.flat[rng.randrange(data.size)] = np.nan
            elif what == "retype":
                data = data.astype("S8") if data.dtype.kind == "f" else data.astype("f4")
            state[name] = data
