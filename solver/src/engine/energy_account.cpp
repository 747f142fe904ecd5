#include "engine/energy_account.hpp"

#include "parallel/threads.hpp"
#include "physics/mass_transfer.hpp"

namespace cellsim {

StoredEnergy stored_energy(const State& s, const EnergyModel& model) {
  StoredEnergy e;
  const FluidParticles& f = s.fluid;
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    e.kinetic_J += 0.5 * f.m[i] * f.v.col(i).squaredNorm();
    e.internal_J += f.m[i] * model.eos.internal_energy_J_kg(f.rho[i]);
  }
  e.kinetic_J += 0.5 * s.wall.mass_kg * s.wall.v.colwise().squaredNorm().sum();
  const BondEnergy bonds = bond_energy(s.wall, model.mesh, model.bonds, model.ramp, s.bond_plastic_elongation_m);
  e.wall_stiff_J = bonds.stiff_J;
  e.wall_contraction_J = bonds.contraction_J;
  e.wall_bending_J = model.bending.energy(s.wall.x);
  if (model.lj) {
    const PairList& pairs = model.fluid_wall;
    for (int i = 0; i < pairs.rows(); ++i)
      for (int q = pairs.offset[static_cast<std::size_t>(i)]; q < pairs.offset[static_cast<std::size_t>(i) + 1]; ++q)
        e.coupling_J +=
            model.lj->potential_J((f.x.col(i) - s.wall.x.col(pairs.index[static_cast<std::size_t>(q)])).squaredNorm());
  }
  e.plate_J = plate_energy_J(s.wall.x, model.plates, s.plates);
  if (model.contact) {
    const CellContactEnergy between = cell_contact_energy(s.wall.x, *model.wall_wall, *model.lamella, *model.contact,
                                                          s.box, s.lamella_intact, s.lamella_peak_opening_m);
    e.contact_J = between.contact_J;
    e.lamella_J = between.lamella_J;
    e.lamella_loss_J = between.lamella_dissipated_J;
  }
  return e;
}

void add_half_kick(const EnergyRates& rates, double half_dt, bool density_flows, EnergyFlows& flows) {
  flows.plate_work_J += half_dt * rates.plate_W;
  flows.viscous_loss_J += half_dt * rates.viscous_loss_W;
  flows.damping_loss_J += half_dt * rates.damping_loss_W;
  if (density_flows) flows.mass_transfer_J += half_dt * rates.mass_transfer_W;
  flows.drive_J += half_dt * rates.drive_W;
  if (density_flows) flows.density_diffusion_J += half_dt * rates.density_diffusion_W;
  flows.backstop_work_J += half_dt * rates.backstop_W;
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

double energy_residual_J(const StoredEnergy& now, const EnergyFlows& flows) {
  const double put_in = flows.plate_work_J - flows.viscous_loss_J - flows.damping_loss_J + flows.mass_transfer_J +
                        flows.closure_J + flows.drive_J + flows.density_diffusion_J + flows.backstop_work_J +
                        flows.volume_closure_J - flows.plastic_loss_J - now.lamella_loss_J;
  return now.total_J() - flows.initial_J - put_in;
}

}  // namespace cellsim
