// The SPH fluid (sph_fluid.hpp): what the step asks of a fluid (fluid_model.hpp), from Eqs 3-11 and the
// wall-fluid coupling.
#include "engine/sph_fluid.hpp"

#include <algorithm>
#include <cmath>

#include "engine/leapfrog.hpp"
#include "engine/sph_energy.hpp"
#include "engine/step_checks.hpp"
#include "parallel/cell_blocks.hpp"
#include "parallel/threads.hpp"
#include "physics/kernel.hpp"
#include "physics/mass_transfer.hpp"
#include "physics/pressure_closure.hpp"
#include "physics/volume_closure.hpp"

namespace cellsim {
namespace {

// The per-particle loops, for particles [begin, end) (one block of for_blocks), with the scalars as
// value parameters (leapfrog.hpp says why).

// Eq 11 for the fluid particles [begin, end) of a cell of n fluid particles and wall area area_m2,
// and their share of the density rate (Eq 9).
void mass_rates(const FluidParticles& f, const Eigen::VectorXd& pressure, double area_m2, int n, double Lp_m_per_s_Pa,
                double osmotic_Pa, Eigen::Index begin, Eigen::Index end, Eigen::VectorXd& dm_dt,
                Eigen::VectorXd& drho_dt) {
  for (Eigen::Index i = begin; i < end; ++i) {
    dm_dt[i] = mass_rate(area_m2, Lp_m_per_s_Pa, f.rho[i], n, pressure[i], osmotic_Pa);
    drho_dt[i] = density_rate(drho_dt[i], f.rho[i], f.m[i], dm_dt[i]);
  }
}

// Half a kick of the fluid: velocity by force / mass, and (density_too: time.density_update = kick)
// density and mass by their rates.
void kick_fluid(double half_dt, const Eigen::Matrix3Xd& force, const Eigen::VectorXd& drho_dt,
                const Eigen::VectorXd& dm_dt, bool density_too, Eigen::Index begin, Eigen::Index end,
                Eigen::VectorXd& kick_factor, FluidParticles& f) {
  const Eigen::Index count = end - begin;
  kick_factor.segment(begin, count) = half_dt / f.m.segment(begin, count).array();  // packed divisions
  for (Eigen::Index i = begin; i < end; ++i) f.v.col(i) += kick_factor[i] * force.col(i);
  if (!density_too) return;
  f.rho.segment(begin, count) += half_dt * drho_dt.segment(begin, count);
  f.m.segment(begin, count) += half_dt * dm_dt.segment(begin, count);
}

// The drift of density and mass over dt (time.density_update = drift): Eq 10's rate plus Eq 9's share
// of Eq 11, with the mass by Eq 11.
void drift_density(double dt, const Eigen::VectorXd& continuity_rate, const Eigen::VectorXd& dm_dt, Eigen::Index begin,
                   Eigen::Index end, FluidParticles& f) {
  for (Eigen::Index i = begin; i < end; ++i) {
    f.rho[i] += dt * density_rate(continuity_rate[i], f.rho[i], f.m[i], dm_dt[i]);
    f.m[i] += dt * dm_dt[i];
  }
}

// y *= factor, for entries [begin, end).
void scale(double factor, Eigen::Index begin, Eigen::Index end, Eigen::VectorXd& y) {
  y.segment(begin, end - begin) *= factor;
}

}  // namespace

SphFluid::SphFluid(const Params& p, const CellRanges& cells, const PropertyFactors& factors)
    : p_(p),
      drift_density_(p.density_update == kDensityDrift),
      lj_{*p.r0_m, 0.0, p.repulsion_f0_N_m, p.attraction_f0_N_m} {
  if (p.viscosity_cv > 0)  // each cell's fluid its own viscosity (heterogeneity.hpp)
    for (int c = 0; c < cells.count(); ++c)
      viscosity_Pa_s_.insert(viscosity_Pa_s_.end(), static_cast<std::size_t>(cells.fluid_count(c)),
                             p.viscosity_Pa_s * factors.viscosity[static_cast<std::size_t>(c)]);
  largest_viscosity_Pa_s_ =
      viscosity_Pa_s_.empty() ? p.viscosity_Pa_s : *std::max_element(viscosity_Pa_s_.begin(), viscosity_Pa_s_.end());
}

// The lattice of the tissue as built, at rest at rho0 (model.md §1).
void SphFluid::fill(State& s, const Tissue& tissue, const WallSurface&) const {
  s.fluid.x = tissue.fluid_x;
  s.fluid.v = Eigen::Matrix3Xd::Zero(3, tissue.fluid_x.cols());
  s.fluid.m = tissue.fluid_mass_kg;
  s.fluid.rho = Eigen::VectorXd::Constant(tissue.fluid_x.cols(), p_.fluid_density_kg_m3);
}

// The particles' sums, their pressures from the density now (Eq 7).
FluidReadings SphFluid::readings(const State& s, const CellRanges& cells, const WallSurface& surface,
                                 const EquationOfState& eos) const {
  const auto& f = s.fluid;
  FluidReadings r;
  for (int c = 0; c < cells.count(); ++c) {
    double pressure_sum = 0;
    for (Eigen::Index i = cells.fluid[c]; i < cells.fluid[c + 1]; ++i) pressure_sum += eos.pressure(f.rho[i]);
    r.cell_mean_pressure_Pa.push_back(pressure_sum / static_cast<double>(cells.fluid_count(c)));
    r.cell_mass_kg.push_back(f.m.segment(cells.fluid[c], cells.fluid_count(c)).sum());
  }
  r.mass_kg = f.m.sum();
  r.max_speed_m_s = std::sqrt(f.v.colwise().squaredNorm().maxCoeff());
  double pressure_sum = 0;
  for (Eigen::Index i = 0; i < f.size(); ++i) pressure_sum += eos.pressure(f.rho[i]);
  r.mean_pressure_Pa = f.size() ? pressure_sum / static_cast<double>(f.size()) : std::nan("");
  r.volume_ratio = (f.m.array() / f.rho.array()).sum() / surface.volume_m3;
  r.kinetic_energy_J = 0.5 * (f.v.colwise().squaredNorm().transpose().array() * f.m.array()).sum();
  return r;
}

// The wall-fluid pair list's cut-off (either coupling): the kernel's support, or LJ's r_c.
double SphFluid::follow_smoothing_length(double h_m) {
  lj_.cutoff_m = p_.coupling_model == kPressure ? 2.0 * h_m : std::max(lj_.r0_m, p_.attraction_cutoff_over_h * h_m);
  return lj_.cutoff_m;
}

// time.density_update = drift (density_update.hpp): the density and mass advance by dt from the
// continuity rates at the drifted positions and the half-step velocities (Eq 10 with delta-SPH, the
// pressure coupling's wall term), and Eq 11's rates of the last force evaluation; the energy these
// carry (Eq 11's water, the diffusion) is counted over the same dt.
void SphFluid::advance_density(State& s, const FluidContext& c, double dt, const EnergyValues& power_W) {
  const CubicSplineKernel kernel(s.smoothing_length_m);
  fluid_pair_terms(s.fluid, c.neighbours.fluid_fluid(), kernel, c.eos, viscosity(), c.threads, continuity_,
                   p_.density_diffusion * s.smoothing_length_m * c.eos.sound_speed_m_s(), PairTerms::Continuity);
  if (p_.coupling_model == kPressure) {
    pressure_coupling_weights(s.fluid.x, s.wall.x, c.surface.vertex_normal, c.neighbours.fluid_wall(), kernel,
                              pressure_coupling_law(s.smoothing_length_m), c.threads, pressure_coupling_scratch_);
    add_pressure_coupling_density_rates(s.fluid, s.wall, c.neighbours.fluid_wall(), pressure_coupling_scratch_,
                                        c.threads, continuity_.drho_dt);
  }
  s.energy.integral[kMassTransfer] += dt * power_W[kMassTransfer];
  s.energy.integral[kDensityDiffusion] += dt * continuity_.density_diffusion_W;
  for_blocks(c.threads, s.fluid.size(), [&](Eigen::Index begin, Eigen::Index end) {
    drift_density(dt, continuity_.drho_dt, dm_dt_, begin, end, s.fluid);
  });
}

// Pressure (Eq 3) and viscous (Eq 4) terms, and (time.density_update = kick) continuity (Eq 10). With
// pairs_fresh, the continuity pass of advance_density went over the same pairs at these positions: its
// kernel gradients are reused.
void SphFluid::compute_forces(State& s, const FluidContext& c, bool pairs_fresh, EnergyValues& power_W) {
  const CubicSplineKernel kernel(s.smoothing_length_m);
  fluid_pair_terms(s.fluid, c.neighbours.fluid_fluid(), kernel, c.eos, viscosity(), c.threads, rates_,
                   p_.density_diffusion * s.smoothing_length_m * c.eos.sound_speed_m_s(),
                   drift_density_ ? PairTerms::Forces : PairTerms::All,
                   drift_density_ && pairs_fresh ? &continuity_ : nullptr);
  power_W[kViscousLoss] = rates_.viscous_loss_W;
  power_W[kDensityDiffusion] = rates_.density_diffusion_W;
}

// Eq 11 for every fluid particle, through its own cell's wall, and its share of the density rate (Eq 9).
void SphFluid::transfer_mass(State& s, const FluidContext& c, EnergyValues& power_W) {
  dm_dt_.resize(s.fluid.size());
  const double osmotic_Pa = -c.eos.turgor_Pa;  // Pi = -P_T (model.md §5)
  for_cell_blocks(c.threads, c.cells.fluid, [&](int cell, Eigen::Index begin, Eigen::Index end) {
    mass_rates(s.fluid, rates_.pressure, c.surface.cell_area_m2[cell], static_cast<int>(c.cells.fluid_count(cell)),
               c.Lp_m_per_s_Pa, osmotic_Pa, begin, end, dm_dt_, rates_.drho_dt);
  });
  power_W[kMassTransfer] = mass_transfer_power_W(s.fluid, dm_dt_, c.eos, c.threads);
}

// The pressure coupling's backstop range follows h (Eq 6) as the fluid spacing does; its pressure is K.
PressureCouplingLaw SphFluid::pressure_coupling_law(double h_m) const {
  return {p_.backstop_range_over_dx * h_m / *p_.h_over_dx, p_.bulk_modulus_Pa};
}

// The wall-fluid coupling (Lennard-Jones or the fluid's pressure, coupling.model).
void SphFluid::couple_to_wall(State& s, const FluidContext& c, bool weights_fresh, Eigen::Matrix3Xd& on_wall,
                              Eigen::Matrix3Xd& backstop_on_wall, EnergyValues& power_W) {
  power_W[kBackstopWork] = 0;
  if (p_.coupling_model == kPressure) {
    const PairList& pairs = c.neighbours.fluid_wall();
    if (!weights_fresh) {
      pressure_coupling_weights(s.fluid.x, s.wall.x, c.surface.vertex_normal, pairs,
                                CubicSplineKernel(s.smoothing_length_m), pressure_coupling_law(s.smoothing_length_m),
                                c.threads, pressure_coupling_scratch_);
      if (!drift_density_)
        add_pressure_coupling_density_rates(s.fluid, s.wall, pairs, pressure_coupling_scratch_, c.threads,
                                            rates_.drho_dt);
    }
    power_W[kBackstopWork] = pressure_coupling_forces(s.fluid, rates_.pressure, s.wall, pairs, c.threads,
                                                      pressure_coupling_scratch_, rates_.force, on_wall,
                                                      backstop_on_wall);
  } else {
    wall_fluid_forces(s.fluid.x, s.wall.x, c.neighbours.fluid_wall(), lj_, c.threads, rates_.force, on_wall,
                      lj_scratch_);
  }
}

void SphFluid::kick(State& s, double half_dt, int threads) {
  kick_factor_.resize(s.fluid.size());
  for_blocks(threads, s.fluid.size(), [&](Eigen::Index begin, Eigen::Index end) {
    kick_fluid(half_dt, rates_.force, rates_.drho_dt, dm_dt_, !drift_density_, begin, end, kick_factor_, s.fluid);
  });
}

double SphFluid::drift(State& s, double dt, int threads) {
  return reduce_blocks<double>(
      threads, s.fluid.size(),
      [&](Eigen::Index begin, Eigen::Index end) { return drift_columns(dt, s.fluid.v, begin, end, s.fluid.x); },
      [](double a, double b) { return std::max(a, b); });
}

// The wall-pressure closure (pressure_closure.hpp), each cell on its own: during drying only.
void SphFluid::apply_drying_closure(State& s, const FluidContext& c, const std::vector<double>& cell_wall_pressure_Pa) {
  const Eigen::VectorXd& P = rates_.pressure;
  const std::vector<double> pressure_sum = sum_by_cell(
      c.threads, c.cells.fluid, [&](Eigen::Index begin, Eigen::Index end) { return P.segment(begin, end - begin).sum(); });
  std::vector<double> factor(pressure_sum.size());
  bool any = false;
  for (int cell = 0; cell < c.cells.count(); ++cell) {
    const double mean_pressure = pressure_sum[cell] / static_cast<double>(c.cells.fluid_count(cell));
    factor[cell] =
        pressure_closure_factor(cell_wall_pressure_Pa[cell], mean_pressure, p_.dt_s, p_.pressure_closure_time_s);
    any = any || factor[cell] != 1.0;
  }
  if (!any) return;
  for (int cell = 0; cell < c.cells.count(); ++cell)
    s.energy.integral[kPressureClosure] +=
        mass_scaling_energy_J(s.fluid, c.eos, factor[cell], c.cells.fluid[cell], c.cells.fluid[cell + 1]);
  for_cell_blocks(c.threads, c.cells.fluid, [&](int cell, Eigen::Index begin, Eigen::Index end) {
    scale(factor[cell], begin, end, s.fluid.m);
  });
}

std::vector<double> SphFluid::cell_volume_ratios(const State& s, const FluidContext& c) const {
  const std::vector<double> sph_volume = sum_by_cell(c.threads, c.cells.fluid, [&](Eigen::Index begin, Eigen::Index end) {
    return (s.fluid.m.segment(begin, end - begin).array() / s.fluid.rho.segment(begin, end - begin).array()).sum();
  });
  std::vector<double> ratio(sph_volume.size());
  for (std::size_t cell = 0; cell < ratio.size(); ++cell) ratio[cell] = sph_volume[cell] / c.surface.cell_volume_m3[cell];
  return ratio;
}

void SphFluid::start_compression(State& s, const FluidContext& c) {
  s.start_volume_ratio = cell_volume_ratios(s, c);  // what the volume closure holds (volume_closure.hpp)
}

// The volume closure (volume_closure.hpp), each cell on its own: during compression only.
void SphFluid::apply_compression_closure(State& s, const FluidContext& c) {
  if (!(*p_.volume_closure_time_s > 0) || s.start_volume_ratio.empty()) return;
  const std::vector<double> ratio = cell_volume_ratios(s, c);
  for (int cell = 0; cell < c.cells.count(); ++cell) {
    const double factor =
        volume_closure_factor(ratio[cell], s.start_volume_ratio[cell], p_.dt_s, *p_.volume_closure_time_s);
    s.energy.integral[kVolumeClosure] +=
        density_scaling_energy_J(s.fluid, c.eos, factor, c.cells.fluid[cell], c.cells.fluid[cell + 1]);
    s.fluid.rho.segment(c.cells.fluid[cell], c.cells.fluid_count(cell)) *= factor;
  }
}

// model.md §7: the CFL limits at the current forces.
std::string SphFluid::time_step_violation(const State& s, const FluidContext& c) const {
  return cellsim::time_step_violation(s.fluid, rates_.force, s.smoothing_length_m, c.eos.sound_speed_m_s(),
                                      largest_viscosity_Pa_s_, p_.fluid_density_kg_m3, p_.dt_s, c.threads);
}

// The LJ coupling stores its potential; the pressure coupling stores nothing of its own (it carries the
// fluid's pressure, whose energy is the internal energy).
void SphFluid::stored_energy(const State& s, const FluidContext& c, EnergyValues& e) const {
  const ParticleEnergy particles = particle_energy(s.fluid, c.eos);
  e[kKinetic] = particles.kinetic_J;
  e[kInternal] = particles.internal_J;
  double coupling_J = 0;
  if (p_.coupling_model != kPressure) {
    const PairList& pairs = c.neighbours.fluid_wall();
    for (int i = 0; i < pairs.rows(); ++i)
      for (int q = pairs.offset[static_cast<std::size_t>(i)]; q < pairs.offset[static_cast<std::size_t>(i) + 1]; ++q)
        coupling_J += lj_.potential_J((s.fluid.x.col(i) - s.wall.x.col(pairs.index[static_cast<std::size_t>(q)])).squaredNorm());
  }
  e[kCouplingPotential] = coupling_J;
}

// sum m (1/rho0 - 1/rho) (eos.hpp).
double SphFluid::stored_energy_per_turgor_m3(const State& s, const EquationOfState& eos) const {
  double per_turgor = 0;
  for (Eigen::Index i = 0; i < s.fluid.size(); ++i) per_turgor += s.fluid.m[i] * eos.internal_energy_per_turgor(s.fluid.rho[i]);
  return per_turgor;
}

std::vector<double> SphFluid::cell_mean_pressure_Pa(const CellRanges& cells) const {
  std::vector<double> mean(static_cast<std::size_t>(cells.count()));
  for (int c = 0; c < cells.count(); ++c) mean[c] = rates_.pressure.segment(cells.fluid[c], cells.fluid_count(c)).mean();
  return mean;
}

}  // namespace cellsim
