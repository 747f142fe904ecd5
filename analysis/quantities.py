"""How the solver's time series are shown: label and the factor from SI to the unit shown.
The names are those of `cellsim outputs` (tests/test_analysis.py keeps them in step)."""
import json
import pathlib

QUANTITIES = {
    "time_s": ("time [us]", 1e6),
    "stage": ("stage (0 drying, 1 compression)", 1.0),
    "step": ("step", 1.0),
    "fluid_mass_kg": ("fluid mass [ng]", 1e12),
    "fluid_mass_ratio": ("M_f / M_f0", 1.0),
    "mean_pressure_Pa": ("mean fluid pressure [kPa]", 1e-3),
    "area_m2": ("wall area [10^3 um^2]", 1e9),
    "volume_m3": ("cell volume [10^6 um^3]", 1e12),
    "fluid_volume_ratio": ("fluid's SPH volume / enclosed volume", 1.0),
    "equivalent_diameter_m": ("equivalent diameter [um]", 1e6),
    "smoothing_length_m": ("smoothing length h [um]", 1e6),
    "cell_height_m": ("cell height [um]", 1e6),
    "equatorial_radius_m": ("equatorial radius [um]", 1e6),
    "max_fluid_speed_m_s": ("fastest fluid particle [m/s]", 1.0),
    "kinetic_energy_fluid_J": ("fluid kinetic energy [pJ]", 1e12),
    "kinetic_energy_wall_J": ("wall kinetic energy [pJ]", 1e12),
    "wall_strain_mean": ("mean wall bond strain", 1.0),
    "wall_tension_N_m": ("mean wall tension [N/m]", 1.0),
    "wall_pressure_Pa": ("pressure carried by the wall [kPa]", 1e-3),
    "plate_top_z_m": ("top plate height [um]", 1e6),
    "plate_bottom_z_m": ("bottom plate height [um]", 1e6),
    "plate_force_top_N": ("top-plate force [uN]", 1e6),
    "plate_force_bottom_N": ("bottom-plate force [uN]", 1e6),
    "contact_area_m2": ("contact area [um^2]", 1e12),
    "contact_count": ("wall particles in contact", 1.0),
    "contact_area_top_m2": ("top-plate contact area [um^2]", 1e12),
    "pressure_load_N": ("mean fluid pressure x top contact area [uN]", 1e6),
    "load_fluid_N": ("load carried by the fluid's push [uN]", 1e6),
    "load_wall_N": ("load carried by the wall's own forces [uN]", 1e6),
    "load_backstop_N": ("load carried by the pressure coupling's backstop [uN]", 1e6),
    "nominal_strain": ("nominal strain (H_c - H)/H_c", 1.0),
    "plate_strain": ("plate strain", 1.0),
    "plate_stress_Pa": ("plate stress [kPa]", 1e-3),
    "section_stress_Pa": ("section stress [kPa]", 1e-3),
    "contact_stress_Pa": ("contact stress [kPa]", 1e-3),
    "footprint_stress_Pa": ("stress over the footprint [kPa]", 1e-3),
    "lamella_intact": ("middle-lamella bonds intact", 1.0),
    "tissue_volume_m3": ("tissue volume (hull) [10^6 um^3]", 1e12),
    "porosity": ("porosity", 1.0),
    "gauge_strain": ("interior gauge strain", 1.0),
    "period_x_m": ("period along x [um]", 1e6),
    "period_y_m": ("period along y [um]", 1e6),
    "lateral_stress_Pa": ("lateral stress [kPa]", 1e-3),
    # the energy account (docs/model.md §8): its terms follow below, from the solver's table
    "stored_energy_J": ("stored energy [nJ]", 1e9),
    "wall_plastic_strain_mean": ("mean plastic strain of the wall's bonds", 1.0),
    "wall_plastic_strain_max": ("largest plastic strain of a wall bond", 1.0),
    "energy_residual_J": ("energy residual [nJ]", 1e9),
    "relaxation_residual": ("largest force left by the relaxation / pressure load", 1.0),
    "relaxation_evaluations": ("force evaluations of the relaxation", 1.0),
}

# The energy account's terms, the solver's own table (`cellsim energy-terms`, kept in config/schema by
# scripts/update-docs), in the solver's order; each term's series is labelled by the table's words.
ENERGY_TERMS = json.loads((pathlib.Path(__file__).resolve().parents[1] / "config" / "schema" /
                           "energy_terms.json").read_text())


def energy_term_label(term):
    """A stored term is an energy ("wall bending energy"); a flow or a loss is named by what it is."""
    return f"{term['label']} energy [nJ]" if term["role"] == "stored" else f"{term['label']} [nJ]"


QUANTITIES.update({term["column"]: (energy_term_label(term), 1e9) for term in ENERGY_TERMS if term["column"]})

# Derived by analysis/aggregate.py from the solver's series, for every run alike.
DERIVED = {
    # Drying ends at steady state, so compressions start at different times: curves against time in
    # compression are drawn against the time since the plates started, as the paper draws them.
    "compression_time_s": ("time in compression [us]", 1e6),
    # The drained bound (Eq 11 in compression): the fluid mass that left since the plates started.
    "compression_mass_lost": ("fluid mass lost in compression [%]", 100.0),
    # What the cells away from the plates feel (model.md §10c): a tissue's gauge, one cell's nominal strain.
    "cell_strain": ("interior strain (gauge; a cell: nominal)", 1.0),
}

DRAWABLE = {**QUANTITIES, **DERIVED}  # what a figure's x and y may name

# The apparent moduli of the summary table (analysis/aggregate.py), what a modulus figure's y may name.
MODULI = {"modulus_MPa_nominal": "over the nominal strain", "modulus_MPa_gauge": "over the interior cells' strain"}


def label(name):
    return DRAWABLE[name][0]


def scale(name):
    return DRAWABLE[name][1]
