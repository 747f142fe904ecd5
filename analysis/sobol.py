"""Variance-based sensitivity (issue 70): first- and total-order Sobol indices of a function over the unit
cube, by Saltelli's sampling scheme (A, B and A with its i-th column from B), the first order by Saltelli
et al. 2010's estimator and the total by Jansen's; and the one-at-a-time shares of a design around a
baseline, as the paper varies its factors.

    S_i  = mean(f(B) (f(A_B^i) - f(A))) / V,      S_Ti = mean((f(A) - f(A_B^i))^2) / (2 V),

V the variance of f over A and B together (Saltelli et al. 2010, Comput. Phys. Commun. 181:259, Table 2).
"""
import numpy as np
from scipy.stats import qmc


def indices(f, d, n, seed):
    """(first order, total order) arrays of length d for a vectorised f over [0, 1]^d, from n base points
    of a scrambled Sobol sequence in 2d dimensions (its two halves A and B)."""
    ab = qmc.Sobol(d=2 * d, scramble=True, seed=seed).random(n)
    a, b = ab[:, :d], ab[:, d:]
    fa, fb = f(a), f(b)
    variance = np.var(np.concatenate([fa, fb]))
    first, total = np.empty(d), np.empty(d)
    for i in range(d):
        abi = a.copy()
        abi[:, i] = b[:, i]
        fabi = f(abi)
        first[i] = np.mean(fb * (fabi - fa)) / variance
        total[i] = 0.5 * np.mean((fa - fabi) ** 2) / variance
    return first, total


def one_at_a_time(f, baseline_unit, points=65):
    """Each factor's share of the one-at-a-time variance: f along the factor's whole range with the others
    at the baseline (the paper's design), its variance over that line, over the sum of those variances.
    For an additive f at any baseline this is the first-order index; where factors interact, it is not."""
    d = len(baseline_unit)
    line = np.linspace(0.0, 1.0, points)
    variances = np.empty(d)
    for i in range(d):
        x = np.tile(baseline_unit, (points, 1))
        x[:, i] = line
        variances[i] = np.var(f(x))
    return variances / variances.sum()
