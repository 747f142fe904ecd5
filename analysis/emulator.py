"""A Gaussian-process emulator of one answer of the cell over a design's factors (issue 70).

Fitted with scikit-learn (a constant times an anisotropic squared-exponential kernel, plus white noise for
what the runs do not repeat: a dynamic cell's ripple, a fold's two landings), then kept as plain numbers so
that this module's predict() and the slider page's JavaScript give the same prediction:

    mean(x) = y_mean + y_std * k(x)^T alpha,   var(x) = (s y_std)^2 * (c + noise - |L^-1 k(x)|^2),
    k_i(x) = c exp(-|(x - x_i) / l|^2 / 2),

with x in the unit cube of the design (analysis/design.py), alpha = (K + noise I)^-1 (y - y_mean) / y_std and L
its Cholesky factor, s = sd_scale (1 unless widened to held-out runs). The variance holds the noise: the band
is where a new run would fall. Answers that span
orders of magnitude (stress, eps) are emulated in their logarithm (`transform: log`).
"""
import warnings

import numpy as np
from scipy.linalg import solve_triangular
from sklearn.gaussian_process import GaussianProcessRegressor
from sklearn.exceptions import ConvergenceWarning
from sklearn.gaussian_process.kernels import RBF, ConstantKernel, WhiteKernel

Z95 = 1.959964  # the two-sided 95 % band of a normal


def forward(y, transform):
    return np.log(y) if transform == "log" else np.asarray(y, dtype=float)


def backward(z, transform):
    return np.exp(z) if transform == "log" else z


def fit(x_unit, y, transform="none", restarts=4, seed=0):
    """The emulator (a dict of plain numbers) of answers y at design points x_unit (n x d, in [0, 1])."""
    z = forward(np.asarray(y, dtype=float), transform)
    d = x_unit.shape[1]
    kernel = (ConstantKernel(1.0, (1e-3, 1e3)) * RBF(np.full(d, 0.5), (1e-2, 1e2))
              + WhiteKernel(1e-3, (1e-8, 1.0)))
    gp = GaussianProcessRegressor(kernel, normalize_y=True, n_restarts_optimizer=restarts, random_state=seed)
    with warnings.catch_warnings():  # a length scale at its bound (a factor that does nothing) is an answer,
        warnings.simplefilter("ignore", ConvergenceWarning)  # not a failure: the held-out check judges the fit
        gp.fit(x_unit, z)
    return exported(gp, x_unit, z, transform)


def exported(gp, x_unit, z, transform):
    """The fitted process as numbers: the training points, alpha, the Cholesky factor and the kernel's
    constants, in the normalised units sklearn fits in."""
    params = gp.kernel_.get_params()
    return {"transform": transform, "x": np.asarray(x_unit, dtype=float),
            "alpha": np.asarray(gp.alpha_, dtype=float).ravel(), "L": np.asarray(gp.L_, dtype=float),
            "constant": float(params["k1__k1__constant_value"]),
            "length_scales": np.atleast_1d(params["k1__k2__length_scale"]).astype(float),
            "noise": float(params["k2__noise_level"]),
            "y_mean": float(np.ravel(gp._y_train_mean)[0]), "y_std": float(np.ravel(gp._y_train_std)[0])}


def refit(emulator, x_unit, y):
    """The same kernel (constants kept) on other training runs: a bootstrap replicate of the emulator."""
    d = x_unit.shape[1]
    kernel = (ConstantKernel(emulator["constant"], "fixed") * RBF(emulator["length_scales"], "fixed")
              + WhiteKernel(emulator["noise"], "fixed"))
    z = forward(np.asarray(y, dtype=float), emulator["transform"])
    gp = GaussianProcessRegressor(kernel, normalize_y=True, optimizer=None).fit(x_unit.reshape(-1, d), z)
    return exported(gp, x_unit, z, emulator["transform"])


def cross_kernel(emulator, x_unit):
    scaled = (np.atleast_2d(x_unit)[:, None, :] - emulator["x"][None, :, :]) / emulator["length_scales"]
    return emulator["constant"] * np.exp(-0.5 * np.sum(scaled ** 2, axis=2))


def predict(emulator, x_unit):
    """(mean, sd) at points x_unit (m x d), in the emulated (transformed) units."""
    k = cross_kernel(emulator, x_unit)
    mean = emulator["y_mean"] + emulator["y_std"] * (k @ emulator["alpha"])
    v = solve_triangular(emulator["L"], k.T, lower=True)
    var = emulator["constant"] + emulator["noise"] - np.sum(v ** 2, axis=0)
    return mean, emulator.get("sd_scale", 1.0) * emulator["y_std"] * np.sqrt(np.maximum(var, 0.0))


def predict_mean(emulator, x_unit):
    """The mean alone (what the Sobol estimators integrate): no triangular solve."""
    return emulator["y_mean"] + emulator["y_std"] * (cross_kernel(emulator, x_unit) @ emulator["alpha"])


def held_out_check(emulator, x_unit, y):
    """How the emulator predicts runs it never saw, in its emulated units: Q^2 = 1 - SS_res / SS_tot, the
    root-mean-square error, and the share of the runs inside the 95 % band."""
    z = forward(np.asarray(y, dtype=float), emulator["transform"])
    mean, sd = predict(emulator, x_unit)
    residual = z - mean
    return {"q2": 1.0 - np.sum(residual ** 2) / np.sum((z - z.mean()) ** 2),
            "rmse": float(np.sqrt(np.mean(residual ** 2))),
            "coverage_95": float(np.mean(np.abs(residual) <= Z95 * sd)),
            "band_95_mean": float(np.mean(Z95 * sd)), "runs": int(len(z))}


def widened_to_held_out(emulator, x_unit, y):
    """The emulator with its sd scaled so that held-out runs sit at one sd on average (rms of residual / sd),
    where they sat further: a process fitted to few runs can be surer than its errors ("sd_scale", >= 1)."""
    z = forward(np.asarray(y, dtype=float), emulator["transform"])
    mean, sd = predict({**emulator, "sd_scale": 1.0}, x_unit)
    return {**emulator, "sd_scale": max(1.0, float(np.sqrt(np.mean(((z - mean) / sd) ** 2))))}


def as_json(emulator):
    """The emulator for the page: arrays as lists (rounded to 12 digits: the page's prediction agrees with
    predict() to far below its band)."""
    return {k: (np.round(v, 12).tolist() if isinstance(v, np.ndarray) else v) for k, v in emulator.items()}


def from_json(numbers):
    """An emulator read back from as_json's numbers."""
    return {k: (np.asarray(v, dtype=float) if isinstance(v, list) else v) for k, v in numbers.items()}
