#pragma once
// The energy account (docs/model.md, "The energy account"), over the table of its terms
// (core/energy_terms.hpp); the force field's terms give their stored energies (force_field.hpp). At every
// record: the energy stored in the particles (kinetic; the fluid's
// internal energy of Eq 7; the wall's stiff, contraction and bending energies; the LJ coupling's
// potential; the plates' springs; a tissue's contacts and lamella), and the running integrals of what the
// non-conservative terms put in or took out (EnergyFlows, state.hpp). What none of them explains is the
// residual: the error of the discretisation (the time
// step, the cut-off r_c = 2h that moves with h, a wall particle entering a plate's footprint inside its
// range) and any term that creates or destroys energy, such as a coupling that is not conservative.
#include "core/energy_terms.hpp"
#include "core/state.hpp"

namespace cellsim {

// The sum of the stored terms, in the table's order.
double stored_energy_J(const EnergyValues& terms);

// The powers (W) of the terms integrated over the half kicks (EnergySource::Power and DensityPower), at
// one force evaluation; each half kick integrates them over its half step (so a step takes their
// trapezoidal mean). density_flows: the DensityPower terms too (Eq 11's water, delta-SPH), when the
// kicks advance the density (time.density_update = kick); with drift the density's own step counts them.
void add_half_kick(const EnergyValues& power_W, double half_dt, bool density_flows, EnergyFlows& flows);

// d/dt of the stored energy at fixed particles while the drying ramps P_T and L_ref (drying.hpp):
// dP_T/dt d(stored)/dP_T (the fluid's, fluid_model.hpp) + c (1 - X) d(ramp)/dt sum k_wc (l - L_ref) l0.
double drive_power_W(double stored_energy_per_turgor_m3, double turgor_rate_Pa_s, double contraction_times_l0_N_m,
                     double L_ref_shortening_rate_1_s);

// Stored energy now - at t = 0 (initial_J) - what the flows and losses put in, each by its sign in the
// table: zero for an exact integration of the model.
double energy_residual_J(const EnergyValues& terms, double initial_J);

// The residual over the magnitudes of every flow and loss since t = 0 (NaN when nothing flowed).
double residual_over_flows(const EnergyValues& terms, double residual_J);

}  // namespace cellsim
