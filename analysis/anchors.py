"""Analytic anchors of the verification ladder (docs/model.md §9): results the model must meet that do
not come from the model itself.

The breathing mode: the lowest radial mode of a compressible fluid sphere (radius R, density rho0,
sound speed c) inside a thin elastic shell (mass mu per area, radial stiffness S_w: the pressure that
pushes it back per metre of radial displacement). With p = A j0(k r), k = omega / c, Euler's equation
at the wall gives its displacement u = p'(R) / (rho0 omega^2), and the shell's motion
-mu omega^2 u = p(R) - S_w u; together
    rho0 omega^2 j0(k R) + (S_w - mu omega^2) k j1(k R) = 0.
A rigid shell gives j1(k R) = 0, k R = 4.493; a compliant one a lower frequency.

The membrane between plates: the wall without its contraction springs (k_wc = 0) is a thin elastic
membrane, a closed bag of the fluid (Eq 7, no water out: its volume V sets P = P_T + K[(V_s/V)^gamma - 1]),
pressed between two rigid, frictionless plates. Axisymmetric and symmetric about the equator, it is solved
here by shooting from the pole (derived in docs/model.md §9): flat where it touches a plate, where the
plate takes P and the plate force is exactly P x the contact area; free elsewhere, where the tensions
balance P; tangent to the plate where it leaves it, vertical at the equator."""
import json

import h5py
import numpy as np
import pandas as pd
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from analysis import aggregate, results


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


# The membrane between plates (docs/model.md §9). The wall's bonds (Eq 15, k_wc = 0) as a membrane: a bond of
# rest length l0 stretched by lambda stores (G t0 l0^2 / sqrt 3)((lambda^2 - 1)/2 - ln lambda); averaged over
# bond directions in a network of sum(l0^2) / A0 = 2 sqrt(3) c (c = 1 for equilateral triangles), the energy
# per reference area is W = M [(l1^2 + l2^2)/4 - 1/2 - ln((l1 + l2)/2)], M = 2 c G t0, in the principal
# stretches l1 (meridional) and l2 (circumferential); the tensions per current length are T1 = W_1 / l2,
# T2 = W_2 / l1. Bending (Eq 20) is left out: a boundary layer of sqrt(k_b / T) ~ 4 um at the contact's rim.

def network_tensions(l1, l2, modulus_N_m):
    """T1, T2 (N/m) and dT1/dl1, dT1/dl2 of the bond network at principal stretches l1, l2."""
    s = l1 + l2
    W1, W2 = modulus_N_m * (l1 / 2 - 1 / s), modulus_N_m * (l2 / 2 - 1 / s)
    return (W1 / l2, W2 / l1, modulus_N_m * (0.5 + 1 / s**2) / l2, modulus_N_m / (s**2 * l2) - W1 / l2**2)


def _meridian(psi, y, radius_m, modulus_N_m, pressure_Pa, touching):
    """d/dpsi of (r, z, phi, l1) along the reference polar angle psi: phi the meridian's angle below the
    horizontal, z measured down from the pole. Tangential balance d(r T1)/ds = T2 cos phi gives l1; normal
    balance T1 dphi/ds + T2 sin phi / r = P gives phi; on the plate phi = 0 and the plate takes P."""
    r, z, phi, l1 = y
    l2 = r / (radius_m * np.sin(psi))
    T1, T2, dT1_dl1, dT1_dl2 = network_tensions(l1, l2, modulus_N_m)
    ds = l1 * radius_m
    dr = ds * np.cos(phi)
    dl2 = (dr - l2 * radius_m * np.cos(psi)) / (radius_m * np.sin(psi))
    dl1 = ((T2 - T1) * dr - r * dT1_dl2 * dl2) / (r * dT1_dl1)
    if touching:
        return [dr, 0.0, 0.0, dl1]
    return [dr, -ds * np.sin(phi), ds * (pressure_Pa - T2 * np.sin(phi) / r) / T1, dl1]


def _shoot(pole_stretch, contact_angle, radius_m, modulus_N_m, pressure_Pa, start=1e-6):
    """The meridian from the pole to the equator (psi = pi/2) for a pole stretch, the reference angle at
    which the membrane leaves the plate (0: no contact) and P: (its free part, its part on the plate)."""
    y = [pole_stretch * radius_m * start, 0.0, 0.0, pole_stretch]
    on_plate, begin = None, start
    tight = dict(rtol=1e-10, atol=1e-14, dense_output=True)
    if contact_angle > start:
        on_plate = solve_ivp(_meridian, (start, contact_angle), y, args=(radius_m, modulus_N_m, pressure_Pa, True),
                             **tight)
        y, begin = on_plate.y[:, -1], contact_angle
    else:  # a free pole is a spherical cap of curvature P / 2T
        y[2] = pressure_Pa / (2 * network_tensions(pole_stretch, pole_stretch, modulus_N_m)[0]) * y[0]
    free = solve_ivp(_meridian, (begin, np.pi / 2), y, args=(radius_m, modulus_N_m, pressure_Pa, False), **tight)
    return free, on_plate


def _volume_m3(free, on_plate, radius_m):
    """Twice the half cell's volume, the integral of pi r^2 |dz| over the free meridian."""
    psi = np.linspace(free.t[0], np.pi / 2, 4001)
    r, _, phi, l1 = free.sol(psi)
    return 2 * np.trapz(np.pi * r**2 * l1 * radius_m * np.sin(phi), psi)


def inflated_stretch(radius_m, modulus_N_m, turgor_Pa):
    """The stretch of the free membrane sphere at P_T (Young-Laplace, P = 2 T / (l R0)). The equibiaxial
    tension is M (1 - 1/l^2), so P rises with l up to l = sqrt 3, where the sphere would burst like a balloon:
    the root is sought below."""
    return brentq(lambda l: 2 * network_tensions(l, l, modulus_N_m)[0] / (l * radius_m) - turgor_Pa, 1 + 1e-12,
                  np.sqrt(3))


def _pole_stretch(contact_angle, radius_m, modulus_N_m, pressure_Pa, guess):
    """The pole stretch whose meridian is vertical at the equator, for this contact angle and P: bracketed
    in widening steps around the guess (the shot is very sensitive to it), then bisected."""
    def mismatch(stretch):
        free, _ = _shoot(stretch, contact_angle, radius_m, modulus_N_m, pressure_Pa)
        angle = free.y[2, -1]
        return angle - np.pi / 2 if free.status == 0 and np.isfinite(angle) else np.nan

    centre = mismatch(guess)
    for width in 1e-5 * 3.0 ** np.arange(7):
        for other in (guess - width, guess + width):
            value = mismatch(other)
            if np.isfinite(value) and np.isfinite(centre) and np.sign(value) != np.sign(centre):
                return brentq(mismatch, *sorted((guess, other)), xtol=1e-14)
    raise ValueError(f"no pole stretch near {guess} meets the equator at contact angle {contact_angle}")


def membrane_between_plates(radius_m, modulus_N_m, turgor_Pa, bulk_modulus_Pa, eos_exponent, largest_strain=0.2,
                            angle_step=0.025):
    """Plate force against nominal strain for the closed membrane cell (reference sphere radius R0,
    modulus M, at rest at P_T) pressed between plates, from the first contact to largest_strain: each row
    the reference contact angle, strain (H_s - H)/H_s (H the cell's height), P, the contact area
    pi r_c^2, the plate force P pi r_c^2, V / V_s and the stretch at the pole. For each contact angle, P is the root of the
    fluid's volume balance, V(P) = V_s [1 + (P - P_T)/K]^(-1/gamma), where V(P) is the volume of the
    meridian whose pole stretch makes it vertical at the equator; each angle starts from the last's."""
    stretch = inflated_stretch(radius_m, modulus_N_m, turgor_Pa)
    start_volume, start_height = 4 / 3 * np.pi * (stretch * radius_m) ** 3, 2 * stretch * radius_m
    rows = [(0.0, 0.0, turgor_Pa, 0.0, 0.0, 1.0, stretch)]
    log_pressure = np.log(turgor_Pa)
    solved = [(0.0, stretch)]  # (contact angle, pole stretch): the next angle's guess goes on along them
    for angle in np.arange(angle_step, np.pi / 2, angle_step):
        if len(solved) > 1:
            (a0, s0), (a1, s1) = solved[-2:]
            stretch = s1 + (s1 - s0) * (angle - a1) / (a1 - a0)
        def volume_mismatch(log_p):
            nonlocal stretch
            pressure = np.exp(log_p)
            stretch = _pole_stretch(angle, radius_m, modulus_N_m, pressure, stretch)
            free, on_plate = _shoot(stretch, angle, radius_m, modulus_N_m, pressure)
            wanted = start_volume * (1 + (pressure - turgor_Pa) / bulk_modulus_Pa) ** (-1 / eos_exponent)
            return np.log(_volume_m3(free, on_plate, radius_m) / wanted)

        try:  # P grows with the contact: bracketed upward from the last angle's in doubling steps
            low, at_low, step = log_pressure, volume_mismatch(log_pressure), 1e-3
            while np.sign(volume_mismatch(low + step)) == np.sign(at_low) and step < 1:
                low, step = low + step, 2 * step
            log_pressure = brentq(volume_mismatch, low, low + step, xtol=1e-12)
        except ValueError:  # past the strains a membrane reaches (it wrinkles at the pole: l < 1)
            break
        pressure = np.exp(log_pressure)
        stretch = _pole_stretch(angle, radius_m, modulus_N_m, pressure, stretch)
        solved.append((angle, stretch))
        free, on_plate = _shoot(stretch, angle, radius_m, modulus_N_m, pressure)
        area = np.pi * on_plate.y[0, -1] ** 2
        height = -2 * free.y[1, -1]
        rows.append((angle, (start_height - height) / start_height, pressure, area, pressure * area,
                     _volume_m3(free, on_plate, radius_m) / start_volume, stretch))
        if rows[-1][1] >= largest_strain:
            break
    names = ["contact_angle", "strain", "pressure_Pa", "contact_area_m2", "force_N", "volume_ratio", "pole_stretch"]
    return {name: np.array([row[i] for row in rows]) for i, name in enumerate(names)}


def network_factor(bonds, rest_length_m, triangles):
    """c = sum(l0^2) / (2 sqrt 3 A0) of a mesh (A0 its triangles' rest areas, by Heron's formula from the
    bonds' rest lengths): 1 for equilateral triangles."""
    length = {(min(a, b), max(a, b)): l for (a, b), l in zip(bonds.tolist(), rest_length_m)}
    edge = lambda a, b: length[(min(a, b), max(a, b))]
    sides = np.array([(edge(a, b), edge(b, c), edge(c, a)) for a, b, c in triangles.tolist()])
    half = sides.sum(axis=1) / 2
    area = np.sqrt(half * (half - sides[:, 0]) * (half - sides[:, 1]) * (half - sides[:, 2])).sum()
    return np.sum(rest_length_m**2) / (2 * np.sqrt(3) * area)


def membrane_of_run(path, largest_strain=0.2, angle_step=0.025):
    """The membrane solution for a result file's cell: its reference radius, its mesh's modulus
    M = 2 c G t0, its turgor and its fluid (the bonds' stiffness without k_wc: docs/model.md §9)."""
    with h5py.File(path) as f:
        case = json.loads(f.attrs["case_json"])
        factor = network_factor(f["mesh"]["bonds"][:], f["mesh"]["bond_rest_length"][:], f["mesh"]["triangles"][:])
    wall, fluid = case["wall"], case["fluid"]
    modulus = 2 * factor * wall["G_MPa"] * 1e6 * wall["thickness_um"] * 1e-6
    turgor = case["cell"]["turgor_kPa"] * 1e3 * case["drying"]["dryness"]
    return membrane_between_plates(case["cell"]["diameter_um"] * 0.5e-6, modulus, turgor,
                                   fluid["bulk_modulus_MPa"] * 1e6, fluid["eos_exponent"], largest_strain, angle_step)


# What each anchor must meet (docs/model-closures.md, "The verification ladder"): the largest relative
# difference from its analytic value.
TOLERANCES = {"breathing mode": 0.05, "Young-Laplace": 0.02, "membrane force": 0.10}


def young_laplace_Pa(volume_m3, wall_tension_N_m):
    """2T/R, R of the enclosed volume: the pressure a membrane of tension T holds at rest."""
    return 2 * wall_tension_N_m / (3 * volume_m3 / (4 * np.pi)) ** (1 / 3)


def _row(anchor, case, level, what, measured, analytic):
    ratio = measured / analytic if analytic else np.nan
    return {"anchor": anchor, "case": case, "resolution": level, "quantity": what, "measured": measured,
            "analytic": analytic, "measured / analytic": ratio, "tolerance": TOLERANCES[anchor],
            "met": bool(abs(ratio - 1) <= TOLERANCES[anchor]) if np.isfinite(ratio) else False}


def breathing_rows(case, level, path):
    """The frequency of the ringing cell's mean pressure against the analytic breathing mode."""
    ts = results.timeseries(path)
    analytic = breathing_frequency_of_run(path)
    measured = dominant_frequency_Hz(ts["time_s"].to_numpy(), ts["mean_pressure_Pa"].to_numpy(), 0.5 * analytic,
                                     2 * analytic)
    return [_row("breathing mode", case, level, "frequency [MHz]", measured / 1e6, analytic / 1e6)]


def young_laplace_rows(case, level, path):
    """At the end of drying, the mean fluid pressure and the pressure the wall carries against 2T/R."""
    ts = results.timeseries(path)
    end = ts[ts["stage"] == 0].iloc[-1]
    laplace = young_laplace_Pa(end["volume_m3"], end["wall_tension_N_m"])
    return [_row("Young-Laplace", case, level, f"{what} at {end['mean_pressure_Pa'] / 1e3:.0f} kPa [kPa]",
                 end[column] / 1e3, laplace / 1e3)
            for what, column in (("mean fluid pressure", "mean_pressure_Pa"), ("wall's pressure", "wall_pressure_Pa"))]


def membrane_rows(case, level, path, strains=(0.05, 0.10)):
    """The plate force at strains 0.05 and 0.10 (mean over +-0.01 strain) against the membrane solution for
    this run's mesh, and F / (P A_c) over strains 0.05-0.15 (1 for a membrane)."""
    ts = results.timeseries(path)
    compression = ts[ts["stage"] == 1]
    solution = membrane_of_run(path, largest_strain=max(strains) + 0.02, angle_step=0.05)
    rows = []
    for strain in strains:
        measured = aggregate.smoothed_stress_at_strain(ts, strain, "plate_force_top_N")
        analytic = np.interp(strain, solution["strain"], solution["force_N"])
        rows.append(_row("membrane force", case, level, f"plate force at strain {strain:.2f} [uN]", measured * 1e6,
                         analytic * 1e6))
    force_ratio = aggregate.load_partition(compression)[0]
    rows.append(_row("membrane force", case, level, "F / (P A_c), strain 0.05-0.15", force_ratio, 1.0))
    return rows


ANCHOR_ROWS = {"breathing": breathing_rows, "laplace": young_laplace_rows, "membrane": membrane_rows}


def anchor_table(runs):
    """runs: [(kind, case name, resolution level, result path)], kind one of ANCHOR_ROWS -> one row per
    anchor quantity: measured, analytic, their ratio, the tolerance and whether it is met."""
    rows = [row for kind, case, level, path in runs for row in ANCHOR_ROWS[kind](case, level, path)]
    return pd.DataFrame(rows, columns=["anchor", "case", "resolution", "quantity", "measured", "analytic",
                                       "measured / analytic", "tolerance", "met"])
