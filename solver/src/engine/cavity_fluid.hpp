#pragma once
// The cell fluid as a closed cell of one uniform pressure (fluid.model = cavity; model.md §11): per cell a
// mass M_f (State::cavity_mass_kg, Eq 11 through the cell's wall area), filling the volume the wall
// encloses at density M_f / V, its pressure Eq 7's, pushing on the wall as P dV/dx_k
// (physics/cavity_pressure.hpp). No particles: no viscosity, no coupling layer, no closures (its
// volume is the enclosed volume and its pressure the wall's by construction). The reference for
// quasi-static answers (quasi_static.hpp), for K up to water's and beyond, and for wall meshes SPH
// cannot afford.
#include <cmath>
#include <string>
#include <vector>

#include "engine/fluid_model.hpp"

namespace cellsim {

class CavityFluid final : public FluidModel, public LeapfrogFluid, public IncrementFluid {
 public:
  explicit CavityFluid(const Params& p);

  void fill(State& s, const Tissue& tissue, const WallSurface& surface) const override;
  double mass_kg(const State& s) const override;
  FluidReadings readings(const State& s, const CellRanges& cells, const WallSurface& surface,
                         const EquationOfState& eos) const override;
  double follow_smoothing_length(double) override { return 0; }  // no wall-fluid pairs
  void compute_forces(State& s, const FluidContext& c, bool pairs_fresh, EnergyValues& power_W) override;
  void transfer_mass(State& s, const FluidContext& c, EnergyValues& power_W) override;
  void couple_to_wall(State& s, const FluidContext& c, bool weights_fresh, Eigen::Matrix3Xd& on_wall,
                      Eigen::Matrix3Xd& backstop_on_wall, EnergyValues& power_W) override;
  void kick(State& s, double half_dt, int threads) override;
  std::string time_step_violation(const State& s, const FluidContext& c) const override;
  void stored_energy(const State& s, const FluidContext& c, EnergyValues& e) const override;
  double stored_energy_per_turgor_m3(const State& s, const EquationOfState& eos) const override;
  std::vector<double> cell_mean_pressure_Pa(const CellRanges&) const override { return pressure_Pa_; }

  // The increments of the quasi-static scheme (fluid_model.hpp's IncrementFluid; physics/cavity_pressure.hpp).
  void begin_increment(const State& s, const FluidContext& c, double dt_s) override;
  double end_increment(State& s, const FluidContext& c) override;
  double increment_work_J(const FluidContext& c) const override;
  // In an increment, Eq 11's backward Euler softens -dP/dV (drained: 0).
  std::vector<double> volume_stiffness_Pa_m3(const EquationOfState& eos) const override;
  Eigen::VectorXd volume_gradients(const WallSurface& surface) const override;

 private:
  double density_in_increment(int cell, double volume_m3, const EquationOfState& eos) const;
  double pressure_work_J(int cell, double volume_m3, const EquationOfState& eos) const;

  double rho0_kg_m3_, dt_s_;
  // At the last force evaluation, per cell: volume, density, pressure, Eq 11's rate, and the time-step
  // limits (Eq 11's relaxation, the volume spring's period).
  std::vector<double> volume_m3_, rho_, pressure_Pa_, dm_dt_;
  double mass_transfer_limit_s_ = INFINITY, volume_mode_limit_s_ = INFINITY;
  // An increment's start (begin_increment): each cell's mass and volume, and dt A L_p (m^3/Pa).
  bool in_increment_ = false;
  std::vector<double> increment_mass_kg_, increment_volume_m3_, increment_a_m3_Pa_;
};

}  // namespace cellsim
