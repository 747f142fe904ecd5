#pragma once
// The energy account (docs/model.md, "The energy account"), over the table of its terms
// (core/energy_terms.hpp). At every record: the energy stored in the particles (kinetic; the fluid's
// internal energy of Eq 7; the wall's stiff, contraction and bending energies; the LJ coupling's
// potential; the plates' springs; a tissue's contacts and lamella), and the running integrals of what the
// non-conservative terms put in or took out (EnergyFlows, state.hpp). What none of them explains is the
// residual: the error of the discretisation (the time
// step, the cut-off r_c = 2h that moves with h, a wall particle entering a plate's footprint inside its
// range) and any term that creates or destroys energy, such as a coupling that is not conservative.
#include "core/state.hpp"
#include "geometry/neighbours.hpp"
#include "geometry/wall_mesh.hpp"
#include "physics/bending.hpp"
#include "physics/cell_contact.hpp"
#include "physics/eos.hpp"
#include "physics/lennard_jones.hpp"
#include "physics/plates.hpp"
#include "physics/wall_bonds.hpp"

namespace cellsim {

// What the stored energy depends on besides the state. lj: null for the pressure coupling, which
// stores nothing of its own (it carries the fluid's pressure, whose energy is the internal energy).
struct EnergyModel {
  const WallMesh& mesh;
  const BondLaw& bonds;
  double ramp;  // of L_ref (drying.hpp)
  const Bending& bending;
  const LennardJones* lj;
  const PairList& fluid_wall;
  const PlateLaw& plates;
  EquationOfState eos;
  const CellContactLaw* contact = nullptr;  // a tissue's (null for one cell), with its pairs and bonds:
  const PairList* wall_wall = nullptr;
  const std::vector<LamellaBond>* lamella = nullptr;
};

// Every term of the account now (core/energy_terms.hpp): the stored energies and the losses that are a
// function of the state (the lamella's damage) from the state; the running integrals from s.energy.
EnergyValues energy_terms(const State& s, const EnergyModel& model);

// The sum of the stored terms, in the table's order.
double stored_energy_J(const EnergyValues& terms);

// The powers (W) of the terms integrated over the half kicks (EnergySource::Power and DensityPower), at
// one force evaluation; each half kick integrates them over its half step (so a step takes their
// trapezoidal mean). density_flows: the DensityPower terms too (Eq 11's water, delta-SPH), when the
// kicks advance the density (time.density_update = kick); with drift the density's own step counts them.
void add_half_kick(const EnergyValues& power_W, double half_dt, bool density_flows, EnergyFlows& flows);

// Sum over the fluid of dm/dt (v^2/2 + e + P/rho): the energy Eq 11's water brings in (threads: as the step's).
double mass_transfer_power_W(const FluidParticles& f, const Eigen::VectorXd& dm_dt, const EquationOfState& eos,
                             int threads);

// The energy a mass scaling of particles [begin, end) by factor (density kept) adds: (factor - 1) sum m (v^2/2 + e).
double mass_scaling_energy_J(const FluidParticles& f, const EquationOfState& eos, double factor, Eigen::Index begin,
                             Eigen::Index end);

// The internal energy a scaling of particles [begin, end)'s densities by factor (masses kept) adds.
double density_scaling_energy_J(const FluidParticles& f, const EquationOfState& eos, double factor, Eigen::Index begin,
                                Eigen::Index end);

// d/dt of the stored energy at fixed particles while the drying ramps P_T and L_ref (drying.hpp):
// dP_T/dt sum m (1/rho0 - 1/rho) + c (1 - X) d(ramp)/dt sum k_wc (l - L_ref) l0.
double drive_power_W(const FluidParticles& f, const EquationOfState& eos, double turgor_rate_Pa_s,
                     double contraction_times_l0_N_m, double L_ref_shortening_rate_1_s);

// Stored energy now - at t = 0 (initial_J) - what the flows and losses put in, each by its sign in the
// table: zero for an exact integration of the model.
double energy_residual_J(const EnergyValues& terms, double initial_J);

}  // namespace cellsim
