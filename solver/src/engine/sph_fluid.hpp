#pragma once
// The cell fluid as SPH particles (model.md §2-5): Eqs 3, 4 and 10 over the fluid pairs, Eq 11's mass
// transfer through each cell's wall, the wall-fluid coupling (Lennard-Jones, Eqs 12-13, or the fluid's
// own pressure: coupling.model), the density advanced in the kicks or the drift (density_update.hpp),
// the drying's pressure closure and the compression's volume closure, and the CFL limits.
#include <string>
#include <vector>

#include "engine/fluid_model.hpp"
#include "geometry/heterogeneity.hpp"
#include "physics/fluid_pairs.hpp"
#include "physics/lennard_jones.hpp"
#include "physics/pressure_coupling.hpp"
#include "physics/wall_fluid.hpp"

namespace cellsim {

class SphFluid final : public FluidModel, public LeapfrogFluid, public ParticleFluid {
 public:
  // factors.viscosity: each cell's fluid its own viscosity (heterogeneity.viscosity_cv), else uniform.
  SphFluid(const Params& p, const CellRanges& cells, const PropertyFactors& factors);

  void fill(State& s, const Tissue& tissue, const WallSurface& surface) const override;
  double mass_kg(const State& s) const override { return s.fluid.m.sum(); }
  FluidReadings readings(const State& s, const CellRanges& cells, const WallSurface& surface,
                         const EquationOfState& eos) const override;
  double follow_smoothing_length(double h_m) override;
  bool density_in_drift() const override { return drift_density_; }
  void advance_density(State& s, const FluidContext& c, double dt, const EnergyValues& power_W) override;
  void compute_forces(State& s, const FluidContext& c, bool pairs_fresh, EnergyValues& power_W) override;
  void transfer_mass(State& s, const FluidContext& c, EnergyValues& power_W) override;
  void couple_to_wall(State& s, const FluidContext& c, bool weights_fresh, Eigen::Matrix3Xd& on_wall,
                      Eigen::Matrix3Xd& backstop_on_wall, EnergyValues& power_W) override;
  void kick(State& s, double half_dt, int threads) override;
  double drift(State& s, double dt, int threads) override;
  void apply_drying_closure(State& s, const FluidContext& c, const std::vector<double>& cell_wall_pressure_Pa) override;
  void start_compression(State& s, const FluidContext& c) override;
  void apply_compression_closure(State& s, const FluidContext& c) override;
  std::string time_step_violation(const State& s, const FluidContext& c) const override;
  void stored_energy(const State& s, const FluidContext& c, EnergyValues& e) const override;
  double stored_energy_per_turgor_m3(const State& s, const EquationOfState& eos) const override;
  std::vector<double> cell_mean_pressure_Pa(const CellRanges& cells) const override;
  const Eigen::Matrix3Xd& particle_force() const override { return rates_.force; }

  // Eq 4's viscosity: uniform, or each fluid particle its cell's (heterogeneity.hpp).
  Viscosity viscosity() const {
    return viscosity_Pa_s_.empty() ? Viscosity(p_.viscosity_Pa_s) : Viscosity(p_.viscosity_Pa_s, viscosity_Pa_s_.data());
  }
  // Each particle's pressure (Eq 7) at the last force evaluation.
  const Eigen::VectorXd& pressure_Pa() const { return rates_.pressure; }

 private:
  PressureCouplingLaw pressure_coupling_law(double h_m) const;  // its backstop range follows h (Eq 6)
  std::vector<double> cell_volume_ratios(const State& s, const FluidContext& c) const;  // sum(m/rho) / enclosed

  Params p_;
  bool drift_density_;
  LennardJones lj_;
  std::vector<double> viscosity_Pa_s_;  // per particle, with heterogeneity.viscosity_cv (else empty)
  double largest_viscosity_Pa_s_ = 0;   // of any cell: the viscous time-step limit

  // Rates at the current positions.
  FluidRates rates_;
  FluidRates continuity_;  // the continuity pass of time.density_update = drift (its forces are zeros)
  Eigen::VectorXd dm_dt_;  // Eq 11
  Eigen::VectorXd kick_factor_;  // scratch, kept to avoid reallocation
  WallFluidScratch lj_scratch_;
  PressureCouplingScratch pressure_coupling_scratch_;
};

}  // namespace cellsim
