"""A study's design (issue 70): instead of the Cartesian product of its axes, a quasi-random set of points
over the ranges of some axes (its factors), each point a case. A scrambled Sobol sequence (scipy.stats.qmc)
gives the training points; a second, independently scrambled sequence the held-out points that check the
emulator; `check` names one more point, off the design, for the slider page's check against a full run.

A factor's range is [low, high] in the axis's own units; `scale: log` spreads the points evenly in its
logarithm (G from 0.18 to 18 MPa). `scales` makes keys follow the factor as a power of its ratio to base:
a larger cell keeps the wall's particle spacing with `cell.n_wall: 2` (the count goes as D^2). Values are
rounded to 4 significant digits, so that case names stay readable; the cases run what their names say.
"""
import math

import numpy as np
from scipy.stats import qmc

SIGNIFICANT_DIGITS = 4


class DesignError(ValueError):
    """A design the config cannot make (names the key)."""


def rounded(value):
    return float(f"{value:.{SIGNIFICANT_DIGITS}g}")


def unit_to_factor(u, spec):
    """A point of [0, 1] -> the factor's value over its range (evenly in the log with scale: log)."""
    low, high = spec["range"]
    if spec.get("scale", "linear") == "log":
        return math.exp(math.log(low) + u * (math.log(high) - math.log(low)))
    return low + u * (high - low)


def factor_to_unit(value, spec):
    """The inverse of unit_to_factor: where a value lies in its range, 0 at low and 1 at high."""
    low, high = spec["range"]
    if spec.get("scale", "linear") == "log":
        return (math.log(value) - math.log(low)) / (math.log(high) - math.log(low))
    return (value - low) / (high - low)


def check(study, spec, axes):
    """Refuses what cannot make a design, naming the key: a factor that is no keyed axis, a factor without
    a range or with low >= high (or <= 0 on a log scale), a check point outside the ranges."""
    where = f"studies.{study}.design"
    for name, factor in spec["factors"].items():
        if name not in axes or "key" not in axes[name]:
            keyed = sorted(a for a, s in axes.items() if "key" in s)
            raise DesignError(f"{where}.factors.{name}: not an axis with a key; a factor must be one of {keyed}")
        if "range" not in factor:
            raise DesignError(f"{where}.factors.{name}: no range; give range: [low, high] in the axis's units")
        low, high = factor["range"]
        if not low < high:
            raise DesignError(f"{where}.factors.{name}.range: [{low}, {high}] is not low < high")
        if factor.get("scale") == "log" and low <= 0:
            raise DesignError(f"{where}.factors.{name}.range: a log scale needs low > 0, got {low}")
    for name, value in spec.get("check", {}).items():
        if name not in spec["factors"]:
            raise DesignError(f"{where}.check.{name}: not one of the design's factors {sorted(spec['factors'])}")
        low, high = spec["factors"][name]["range"]
        if not low <= value <= high:
            raise DesignError(f"{where}.check.{name} = {value}: outside its range [{low}, {high}]")
    if set(spec.get("check", {})) not in (set(), set(spec["factors"])):
        missing = sorted(set(spec["factors"]) - set(spec["check"]))
        raise DesignError(f"{where}.check: gives no value for the factors {missing}")


def unit_points(n, dimensions, seed):
    """n points of a scrambled Sobol sequence in [0, 1)^dimensions (n a power of 2 keeps its balance)."""
    sampler = qmc.Sobol(d=dimensions, scramble=True, seed=seed)
    return sampler.random(n)


def points(spec):
    """[(role, {factor: value})]: the training points, the held-out points (a second sequence, seeded
    seed + 1), and the check point if the design names one."""
    factors = list(spec["factors"])
    out = []
    for role, n, seed in (("train", spec["points"], spec["seed"]), ("held_out", spec.get("held_out", 0), spec["seed"] + 1)):
        if n:
            for u in unit_points(n, len(factors), seed):
                out.append((role, {f: rounded(unit_to_factor(x, spec["factors"][f])) for f, x in zip(factors, u)}))
    if spec.get("check"):
        out.append(("check", {f: float(spec["check"][f]) for f in factors}))
    return out


def scaled(start, ratio, power):
    """A key a factor scales (`scales: {key: power}`): its base value x ratio^power, where ratio is the
    factor's value over its base value; integer keys (particle counts) stay integers."""
    value = start * ratio ** power
    return int(round(value)) if isinstance(start, int) else rounded(value)


def unit_matrix(frame, spec):
    """The design's factor values (columns of a table, one row per run) as points of [0, 1]^d, in the
    design's order of factors: the emulator's inputs."""
    return np.column_stack([[factor_to_unit(v, spec["factors"][f]) for v in frame[f]] for f in spec["factors"]])
