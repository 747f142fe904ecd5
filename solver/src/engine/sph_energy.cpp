#include "engine/sph_energy.hpp"

#include "parallel/threads.hpp"
#include "physics/mass_transfer.hpp"

namespace cellsim {

ParticleEnergy particle_energy(const FluidParticles& f, const EquationOfState& eos) {
  ParticleEnergy e;
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    e.kinetic_J += 0.5 * f.m[i] * f.v.col(i).squaredNorm();
    e.internal_J += f.m[i] * eos.internal_energy_J_kg(f.rho[i]);
  }
  return e;
}

double mass_transfer_power_W(const FluidParticles& f, const Eigen::VectorXd& dm_dt, const EquationOfState& eos,
                             int threads) {
  return reduce_blocks<double>(
      threads, f.size(),
      [&](Eigen::Index begin, Eigen::Index end) {
        const EquationOfState::Enthalpy enthalpy = eos.enthalpy();
        double power[4] = {0, 0, 0, 0};  // four running sums: one would wait on every addition
        for (Eigen::Index i = begin; i < end; ++i)
          power[i & 3] += dm_dt[i] * carried_energy_J_kg(f.v.col(i).squaredNorm(), enthalpy(f.rho[i]));
        return (power[0] + power[1]) + (power[2] + power[3]);
      },
      [](double a, double b) { return a + b; });
}

double mass_scaling_energy_J(const FluidParticles& f, const EquationOfState& eos, double factor, Eigen::Index begin,
                             Eigen::Index end) {
  double energy = 0;
  for (Eigen::Index i = begin; i < end; ++i)
    energy += f.m[i] * (0.5 * f.v.col(i).squaredNorm() + eos.internal_energy_J_kg(f.rho[i]));
  return (factor - 1.0) * energy;
}

double density_scaling_energy_J(const FluidParticles& f, const EquationOfState& eos, double factor, Eigen::Index begin,
                                Eigen::Index end) {
  double energy = 0;
  for (Eigen::Index i = begin; i < end; ++i)
    energy += f.m[i] * (eos.internal_energy_J_kg(factor * f.rho[i]) - eos.internal_energy_J_kg(f.rho[i]));
  return energy;
}

}  // namespace cellsim
