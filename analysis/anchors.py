"""Analytic anchors of the verification ladder (docs/model.md §9): results the model must meet that do
not come from the model itself.

The breathing mode: the lowest radial mode of a compressible fluid sphere (radius R, density rho0,
sound speed c) inside a thin elastic shell (mass mu per area, radial stiffness S_w: the pressure that
pushes it back per metre of radial displacement). With p = A j0(k r), k = omega / c, Euler's equation
at the wall gives its displacement u = p'(R) / (rho0 omega^2), and the shell's motion
-mu omega^2 u = p(R) - S_w u; together
    rho0 omega^2 j0(k R) + (S_w - mu omega^2) k j1(k R) = 0.
A rigid shell gives j1(k R) = 0, k R = 4.493; a compliant one a lower frequency."""
import json

import h5py
import numpy as np


def j0(x):
    return np.sin(x) / x


def j1(x):
    return np.sin(x) / x**2 - np.cos(x) / x


def breathing_frequency_Hz(radius_m, rho0_kg_m3, sound_speed_m_s, stiffness_Pa_m, mass_kg_m2):
    """The lowest root of the equation above, as a frequency (bracketed on a fine grid, then bisected)."""
    def residual(omega):
        k = omega / sound_speed_m_s
        shell = (stiffness_Pa_m - mass_kg_m2 * omega**2) * k * j1(k * radius_m)
        return rho0_kg_m3 * omega**2 * j0(k * radius_m) + shell

    rigid = 4.4934 * sound_speed_m_s / radius_m  # the rigid shell's root bounds the lowest one from above
    grid = np.linspace(1e-3 * rigid, 1.5 * rigid, 20001)
    values = residual(grid)
    first = np.nonzero(np.sign(values[:-1]) != np.sign(values[1:]))[0]
    if not len(first):
        raise ValueError("no radial mode below 1.5 times the rigid shell's")
    lo, hi = grid[first[0]], grid[first[0] + 1]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if np.sign(residual(mid)) != np.sign(residual(lo)) else (mid, hi)
    return 0.5 * (lo + hi) / (2 * np.pi)


def shell_radial_stiffness_Pa_m(bond_length_m, bond_stiffness_N_m, area_m2, tension_N_m, radius_m):
    """S_w of a spring network under tension T: a radial displacement u stretches every bond by l u / R,
    its tension (force per length, sum of F l / 2A) by u/R sum k l^2 / 2A, and Young-Laplace's 2T/R by
    (u/R^2)(sum k l^2 / A - 2T)."""
    return (np.sum(bond_stiffness_N_m * bond_length_m**2) / area_m2 - 2 * tension_N_m) / radius_m**2


def breathing_frequency_of_run(path):
    """The analytic breathing frequency of a result file's cell at its first record (at rest): the EOS's
    sound speed, and the wall's bonds (Eq 15's stiff spring, dF/dl = (G t0 / sqrt 3)(1 + (l0/l)^2), and
    Eq 21's k_wc) and mass (cell.wall_mass_fraction of the fluid's)."""
    with h5py.File(path) as f:
        case = json.loads(f.attrs["case_json"])
        ts = f["timeseries"]
        volume, area, tension = ts["volume_m3"][0], ts["area_m2"][0], ts["wall_tension_N_m"][0]
        wall_x = f["snapshots"][sorted(f["snapshots"])[0]]["wall_positions"][:]
        bonds, rest = f["mesh"]["bonds"][:], f["mesh"]["bond_rest_length"][:]
    radius = (3 * volume / (4 * np.pi)) ** (1 / 3)
    length = np.linalg.norm(wall_x[bonds[:, 1]] - wall_x[bonds[:, 0]], axis=1)
    wall = case["wall"]
    stiff = wall["G_MPa"] * 1e6 * wall["thickness_um"] * 1e-6 / np.sqrt(3) * (1 + (rest / length) ** 2)
    stiffness = shell_radial_stiffness_Pa_m(length, stiff + wall["contraction_stiffness_N_m"], area, tension, radius)
    rho0 = case["cell"]["fluid_density_kg_m3"]
    sound_speed = np.sqrt(case["fluid"]["eos_exponent"] * case["fluid"]["bulk_modulus_MPa"] * 1e6 / rho0)
    diameter = case["cell"]["diameter_um"] * 1e-6
    mass_per_area = case["cell"]["wall_mass_fraction"] * rho0 * np.pi * diameter**3 / 6 / area
    return breathing_frequency_Hz(radius, rho0, sound_speed, stiffness, mass_per_area)


def dominant_frequency_Hz(time_s, values, lowest_Hz, highest_Hz):
    """The strongest frequency of a record between two bounds: a quadratic trend removed, a Hann window,
    and the spectrum zero-padded 32 times so its peak falls between the bins."""
    y = values - np.polyval(np.polyfit(time_s, values, 2), time_s)
    n = 32 * len(y)
    spectrum = np.abs(np.fft.rfft(y * np.hanning(len(y)), n=n))
    frequency = np.fft.rfftfreq(n, time_s[1] - time_s[0])
    band = (frequency >= lowest_Hz) & (frequency <= highest_Hz)
    return frequency[band][np.argmax(spectrum[band])]
