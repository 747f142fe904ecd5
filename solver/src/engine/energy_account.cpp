#include "engine/energy_account.hpp"

#include "parallel/threads.hpp"
#include "physics/mass_transfer.hpp"

namespace cellsim {

EnergyValues energy_terms(const State& s, const EnergyModel& model) {
  EnergyValues e = s.energy.integral;  // the integrated terms (zero in the others' slots); the others set below
  double kinetic_J = 0, internal_J = 0;
  const FluidParticles& f = s.fluid;
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    kinetic_J += 0.5 * f.m[i] * f.v.col(i).squaredNorm();
    internal_J += f.m[i] * model.eos.internal_energy_J_kg(f.rho[i]);
  }
  e[kKinetic] = kinetic_J + 0.5 * s.wall.mass_kg * s.wall.v.colwise().squaredNorm().sum();
  e[kInternal] = internal_J;
  const BondEnergy bonds = bond_energy(s.wall, model.mesh, model.bonds, model.ramp, s.bond_plastic_elongation_m);
  e[kWallStiff] = bonds.stiff_J;
  e[kWallContraction] = bonds.contraction_J;
  e[kWallBending] = model.bending.energy(s.wall.x);
  double coupling_J = 0;
  if (model.lj) {
    const PairList& pairs = model.fluid_wall;
    for (int i = 0; i < pairs.rows(); ++i)
      for (int q = pairs.offset[static_cast<std::size_t>(i)]; q < pairs.offset[static_cast<std::size_t>(i) + 1]; ++q)
        coupling_J +=
            model.lj->potential_J((f.x.col(i) - s.wall.x.col(pairs.index[static_cast<std::size_t>(q)])).squaredNorm());
  }
  e[kCouplingPotential] = coupling_J;
  e[kPlateSprings] = plate_energy_J(s.wall.x, model.plates, s.plates);
  if (model.contact) {
    const CellContactEnergy between = cell_contact_energy(s.wall.x, *model.wall_wall, *model.lamella, *model.contact,
                                                          s.box, s.lamella_intact, s.lamella_peak_opening_m);
    e[kContact] = between.contact_J;
    e[kLamella] = between.lamella_J;
    e[kLamellaLoss] = between.lamella_dissipated_J;
  }
  return e;
}

double stored_energy_J(const EnergyValues& terms) {
  double total = 0;
  for (const EnergyTerm& term : kEnergyTerms)
    if (term.role == EnergyRole::Stored) total += terms[term.id];
  return total;
}

void add_half_kick(const EnergyValues& power_W, double half_dt, bool density_flows, EnergyFlows& flows) {
  for (const EnergyTerm& term : kEnergyTerms)
    if (term.source == EnergySource::Power || (density_flows && term.source == EnergySource::DensityPower))
      flows.integral[term.id] += half_dt * power_W[term.id];
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

double drive_power_W(const FluidParticles& f, const EquationOfState& eos, double turgor_rate_Pa_s,
                     double contraction_times_l0_N_m, double L_ref_shortening_rate_1_s) {
  double per_turgor = 0;  // d(stored energy)/dP_T = sum m (1/rho0 - 1/rho)
  for (Eigen::Index i = 0; i < f.size(); ++i) per_turgor += f.m[i] * eos.internal_energy_per_turgor(f.rho[i]);
  return turgor_rate_Pa_s * per_turgor + L_ref_shortening_rate_1_s * contraction_times_l0_N_m;
}

double energy_residual_J(const EnergyValues& terms, double initial_J) {
  double put_in = 0;
  for (const EnergyTerm& term : kEnergyTerms)
    if (term.role != EnergyRole::Stored) put_in += residual_sign(term.role) * terms[term.id];
  return stored_energy_J(terms) - initial_J - put_in;
}

}  // namespace cellsim
