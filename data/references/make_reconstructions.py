"""Reconstructs fresh-apple tissue compression curves from published summary numbers.

Source: Chakespari, Rajabipour & Mobli, "Strength behavior study of apples under compression
loading", Modern Applied Science (CC BY). Reported per cultivar: failure stress and strain,
initial tangent modulus and tangent modulus. No measured stress-strain points are available, so
each curve here is the cubic through the origin with the initial tangent modulus as its slope at
zero strain and the failure point with the tangent modulus as its slope there. It is a
reconstruction, labelled as such wherever it is drawn.

Run: /usr/bin/python3 data/references/make_reconstructions.py (rewrites the CSV files).
"""
import pathlib

import numpy as np

CULTIVARS = {
    # name: (failure stress MPa, failure strain, initial tangent modulus MPa, tangent modulus MPa)
    "chakespari_red_delicious": (0.37, 0.312, 0.93, 2.27),
    "chakespari_golden_delicious": (0.32, 0.234, 0.81, 2.08),
}


def cubic(sigma_f, eps_f, e0, et):
    """sigma(eps) = e0 eps + b eps^2 + c eps^3 with sigma(eps_f) = sigma_f, sigma'(eps_f) = et."""
    c = (et + e0 - 2 * sigma_f / eps_f) / eps_f**2
    b = (sigma_f - e0 * eps_f - c * eps_f**3) / eps_f**2
    return lambda eps: e0 * eps + b * eps**2 + c * eps**3


if __name__ == "__main__":
    here = pathlib.Path(__file__).parent
    for name, (sigma_f, eps_f, e0, et) in CULTIVARS.items():
        curve = cubic(sigma_f, eps_f, e0, et)
        eps = np.linspace(0, eps_f, 41)
        sigma = curve(eps)
        assert np.all(np.diff(sigma) > 0), name  # a monotone loading curve
        lines = ["# strain [1], stress [MPa]; RECONSTRUCTED, see make_reconstructions.py"]
        lines += [f"{e:.5f},{s:.6f}" for e, s in zip(eps, sigma)]
        (here / f"{name}.csv").write_text("\n".join(lines) + "\n")
        print("wrote", name)
