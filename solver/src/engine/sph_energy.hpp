#pragma once
// The SPH fluid's share of the energy account (energy_account.hpp, core/energy_terms.hpp): its particles'
// kinetic and internal energy (Eq 7), what Eq 11's water carries in, and what the closures' scalings add.
#include <Eigen/Core>

#include "core/state.hpp"
#include "physics/eos.hpp"

namespace cellsim {

// The fluid particles' kinetic energy and internal energy (Eq 7's, by eos.hpp).
struct ParticleEnergy {
  double kinetic_J = 0, internal_J = 0;
};
ParticleEnergy particle_energy(const FluidParticles& f, const EquationOfState& eos);

// Sum over the fluid of dm/dt (v^2/2 + e + P/rho): the energy Eq 11's water brings in (threads: as the step's).
double mass_transfer_power_W(const FluidParticles& f, const Eigen::VectorXd& dm_dt, const EquationOfState& eos,
                             int threads);

// The energy a mass scaling of particles [begin, end) by factor (density kept) adds: (factor - 1) sum m (v^2/2 + e).
double mass_scaling_energy_J(const FluidParticles& f, const EquationOfState& eos, double factor, Eigen::Index begin,
                             Eigen::Index end);

// The internal energy a scaling of particles [begin, end)'s densities by factor (masses kept) adds.
double density_scaling_energy_J(const FluidParticles& f, const EquationOfState& eos, double factor, Eigen::Index begin,
                                Eigen::Index end);

}  // namespace cellsim
