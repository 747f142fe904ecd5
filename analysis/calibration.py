"""The calibrate target (issue 70): the posterior of a wall's unknowns given measured numbers, by MCMC (emcee)
on emulators of a design's runs (analysis/emulator.py), each target's likelihood widened by its emulator's
own uncertainty at the point:

    ln L(theta) = -1/2 sum_j (y_j - m_j(theta))^2 / (sigma_j^2 + s_j(theta)^2) + ln(sigma_j^2 + s_j(theta)^2),

y_j the measured value (its logarithm for a target given with sigma_ln), m_j and s_j the emulator's mean and
sd there. The prior is uniform over each unknown's design range (in the logarithm for a log-scale factor);
the design varies the unknowns and nothing else (its other axes are fixed by its `vary`).

Refused, naming what is wrong: a target with no uncertainty, an unknown with no prior range, and an emulator
whose error on the held-out runs exceeds the target's uncertainty (its posterior would be the emulator's).
"""
import emcee
import numpy as np
import pandas as pd

from analysis import design, emulator
from analysis.design_runs import DRYING_OUTPUTS, RECORDED_STRAINS, stress_column


class CalibrationError(ValueError):
    """A calibration that cannot be trusted or made (names the key or the numbers)."""


def target_columns(name, spec):
    """[(column of the design table, measured value, its sd, 'log' or 'none')] of one target: one for a
    value, one per strain for a curve."""
    where = f"calibration.targets.{name}"
    if "sigma" not in spec and "sigma_ln" not in spec:
        raise CalibrationError(f"{where}: no uncertainty; give sigma (in its units) or sigma_ln (of its "
                               f"logarithm): a target without one would be believed exactly")
    if "sigma" in spec and "sigma_ln" in spec:
        raise CalibrationError(f"{where}: give sigma or sigma_ln, not both")
    scale, sigma = ("log", spec["sigma_ln"]) if "sigma_ln" in spec else ("none", spec["sigma"])
    for key in ("quantity", "value", "provenance"):
        if key not in spec:
            raise CalibrationError(f"{where}: no {key}")
    values = spec["value"] if isinstance(spec["value"], list) else [spec["value"]]
    sigmas = sigma if isinstance(sigma, list) else [sigma] * len(values)
    if spec["quantity"] == "stress_kPa":
        strains = spec.get("strains", [])
        if len(strains) != len(values) or len(sigmas) != len(values):
            raise CalibrationError(f"{where}: a curve needs as many strains, values and sigmas ({len(strains)}, "
                                   f"{len(values)}, {len(sigmas)})")
        off = [e for e in strains if not any(abs(e - r) < 1e-9 for r in RECORDED_STRAINS)]
        if off:
            raise CalibrationError(f"{where}.strains: {off} are not among the strains a design records, "
                                   f"{list(RECORDED_STRAINS)}")
        columns = [stress_column(e) for e in strains]
    else:
        if len(values) != 1 or spec["quantity"] not in DRYING_OUTPUTS:
            raise CalibrationError(f"{where}: {spec['quantity']} is one value")
        columns = [spec["quantity"]]
    if any(not s > 0 for s in sigmas):
        raise CalibrationError(f"{where}: its uncertainty must be > 0, got {sigmas}")
    if scale == "log" and any(not v > 0 for v in values):
        raise CalibrationError(f"{where}: sigma_ln needs values > 0, got {values}")
    suffix = "".join(f"@{axis}={value:g}" for axis, value in sorted(spec.get("where", {}).items()))
    return [(c + suffix, float(v), float(s), scale) for c, v, s in zip(columns, values, sigmas)]


def check(config):
    """The calibration's own cross-references; returns (design spec, unknowns, targets as columns)."""
    spec = config["calibration"]
    study = spec["study"]
    if study not in config["studies"] or "design" not in config["studies"][study]:
        raise CalibrationError(f"calibration.study: '{study}' is not a study with a design")
    factors = config["studies"][study]["design"]["factors"]
    for unknown in spec["unknowns"]:
        if unknown not in factors:
            raise CalibrationError(f"calibration.unknowns: '{unknown}' has no prior range: it is not a factor of "
                                   f"studies.{study}.design (factors: {sorted(factors)}); add it there with its range")
    held = sorted(set(factors) - set(spec["unknowns"]))
    if held:
        raise CalibrationError(f"calibration.unknowns: the design also varies {held}; name them as unknowns or "
                               f"take them out of studies.{study}.design.factors")
    varied = config["studies"][study]["vary"]
    targets = []
    several = sorted(a for a, values in varied.items() if len(values) > 1)
    for name, target in spec["targets"].items():
        if sorted(target.get("where", {})) != several:
            raise CalibrationError(f"calibration.targets.{name}.where: must give the value of each axis studies.{study} "
                                   f"runs at several values, {several}; it gives {sorted(target.get('where', {}))}")
        for axis, value in target.get("where", {}).items():
            if axis not in varied or not any(matches(value, v) for v in varied[axis]):
                raise CalibrationError(f"calibration.targets.{name}.where.{axis} = {value}: studies.{study} runs "
                                       f"{axis} at {varied.get(axis, 'its base value only')}")
        targets += [(name, *column) for column in target_columns(name, target)]
    return config["studies"][study]["design"], spec["unknowns"], targets


def matches(a, b):
    return a == b if isinstance(a, str) or isinstance(b, str) else abs(a - b) <= 1e-9 * max(1.0, abs(b))


def judge_emulators(emulators, held, x_held, targets):
    """One row per target column: the emulator's held-out RMSE in the target's units against the target's sd.
    An emulator whose error exceeds the sd is refused (CalibrationError naming it and both numbers)."""
    rows = []
    for name, column, value, sigma, scale in targets:
        em = emulators[column]
        mean, _ = emulator.predict(em, x_held)
        predicted = emulator.backward(mean, em["transform"])
        runs = held[column].to_numpy(dtype=float)
        error = (np.log(predicted) - np.log(runs)) if scale == "log" else predicted - runs
        rmse = float(np.sqrt(np.mean(error ** 2)))
        rows.append({"target": name, "column": column, "held_out_rmse": rmse, "sigma": sigma, "scale": scale,
                     "runs": len(runs)})
        if not rmse < sigma:
            raise CalibrationError(f"calibration.targets.{name}: the emulator of {column} misses its {len(runs)} "
                                   f"held-out runs by {rmse:.3g} (rms{', in ln' if scale == 'log' else ''}), more "
                                   f"than the target's uncertainty {sigma:.3g}: its posterior would be the "
                                   f"emulator's error. Run a larger design (studies.*.design.points)")
    return pd.DataFrame(rows)


def log_posterior_function(emulators, targets, factors, unknowns):
    """ln p(theta | data) up to a constant for rows theta of the unknowns' unit cube (uniform prior there;
    -inf outside), vectorised over the rows."""
    order = [unknowns.index(f) for f in factors]

    def log_posterior(theta):
        theta = np.atleast_2d(theta)
        inside = np.all((theta >= 0.0) & (theta <= 1.0), axis=1)
        total = np.where(inside, 0.0, -np.inf)
        u = np.clip(theta[:, order], 0.0, 1.0)
        for _name, column, value, sigma, scale in targets:
            em = emulators[column]
            m, s = emulator.predict(em, u)
            if em["transform"] == "log" and scale == "none":  # a value's sd from a log emulator (delta method)
                m, s = np.exp(m), np.exp(m) * s
            elif em["transform"] == "none" and scale == "log":
                m, s = np.log(np.maximum(m, 1e-300)), s / np.maximum(np.abs(m), 1e-300)
            y = np.log(value) if scale == "log" else value
            variance = sigma ** 2 + s ** 2
            total = total - 0.5 * ((y - m) ** 2 / variance + np.log(variance))
        return total
    return log_posterior


ENOUGH_AUTOCORRELATION_TIMES = 50  # emcee's advice for the kept chain
MORE_STEPS_AT_MOST = 4              # a chain that mixes slowly is run on, up to this many times its steps


def sample(log_posterior, dimensions, sampler_spec):
    """emcee's ensemble sampler from points spread over the prior, run on (doubling) until the kept chain is
    50 autocorrelation times long or MORE_STEPS_AT_MOST times its steps; (flat chain after burn-in,
    diagnostics)."""
    walkers, steps = sampler_spec.get("walkers", 32), sampler_spec.get("steps", 3000)
    burn, seed = sampler_spec.get("burn", steps // 3), sampler_spec.get("seed", 1)
    if burn >= steps:
        raise CalibrationError(f"calibration.sampler.burn = {burn}: must be below its steps ({steps})")
    rng = np.random.RandomState(seed)
    start = rng.uniform(0.0, 1.0, (walkers, dimensions))
    mcmc = emcee.EnsembleSampler(walkers, dimensions, log_posterior, vectorize=True)
    mcmc.random_state = rng.get_state()
    mcmc.run_mcmc(start, steps, progress=False)
    ran = steps
    while True:
        chain = mcmc.get_chain(discard=burn)
        tau = emcee.autocorr.integrated_time(chain, tol=0)
        if (ran - burn) / np.max(tau) >= ENOUGH_AUTOCORRELATION_TIMES or ran >= MORE_STEPS_AT_MOST * steps:
            break
        mcmc.run_mcmc(None, ran, progress=False)
        ran *= 2
    diagnostics = {"walkers": walkers, "steps": ran, "steps_asked": steps, "burn": burn,
                   "acceptance_mean": float(np.mean(mcmc.acceptance_fraction)),
                   "acceptance_min": float(np.min(mcmc.acceptance_fraction)),
                   "autocorrelation_steps": [float(t) for t in tau],
                   "kept_over_autocorrelation": float((ran - burn) / np.max(tau)),
                   "independent_samples": float(walkers * (ran - burn) / np.max(tau))}
    return chain.reshape(-1, dimensions), diagnostics


def to_values(flat_unit, unknowns, factor_specs):
    """Samples of the unit cube -> the unknowns' values (a table, one column per unknown)."""
    return pd.DataFrame({u: [design.unit_to_factor(x, factor_specs[u]) for x in flat_unit[:, i]]
                         for i, u in enumerate(unknowns)})


def posterior_table(samples, unknowns, factor_specs):
    """Per unknown: the prior range, the posterior median and 5-95 % interval."""
    rows = []
    for u in unknowns:
        q = np.percentile(samples[u], [5, 50, 95])
        rows.append({"unknown": u, "prior_low": factor_specs[u]["range"][0], "prior_high": factor_specs[u]["range"][1],
                     "prior_scale": factor_specs[u].get("scale", "linear"),
                     "median": q[1], "p05": q[0], "p95": q[2]})
    return pd.DataFrame(rows)


def predictive(emulators, targets, flat_unit, unknowns, factors, draws=2000, seed=2):
    """Per target column: the posterior predictive (emulator mean plus its noise, at posterior draws) as
    5/50/95 % beside the measured value and its 90 % interval."""
    rng = np.random.default_rng(seed)
    pick = flat_unit[rng.integers(0, len(flat_unit), min(draws, len(flat_unit)))]
    u = pick[:, [unknowns.index(f) for f in factors]]
    rows = []
    for name, column, value, sigma, scale in targets:
        em = emulators[column]
        mean, sd = emulator.predict(em, u)
        draw = emulator.backward(mean + sd * rng.standard_normal(len(mean)), em["transform"])
        q = np.percentile(draw, [5, 50, 95])
        low, high = ((value * np.exp(-1.645 * sigma), value * np.exp(1.645 * sigma)) if scale == "log"
                     else (value - 1.645 * sigma, value + 1.645 * sigma))
        rows.append({"target": name, "column": column, "measured": value, "measured_p05": low, "measured_p95": high,
                     "predicted_p05": q[0], "predicted_median": q[1], "predicted_p95": q[2]})
    return pd.DataFrame(rows)
