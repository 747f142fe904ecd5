#pragma once
// What the engine asks of a cell's fluid, in the faces each scheme asks for (model.md §2-5, §7, §11):
// - FluidModel, what both schemes need: fill, its rates and Eq 11's mass transfer, its push on the wall
//   (the force field's fluid term, force_terms.hpp), its share of the energy account, its readings;
// - LeapfrogFluid, what only the leapfrog asks of every fluid: the kick, and the fluid's time-step limit;
// - ParticleFluid, what the leapfrog asks of a fluid of particles only: the density's drift step, the
//   drift, the drying's and the compression's closures, the particles' forces (the settle's FIRE reads them);
// - IncrementFluid, what only the quasi-static scheme asks: Eq 11's increment, its potential, the volume
//   stiffness and the pressures' follower stiffness.
// A model implements the faces it has, and make_fluid hands them out as a Fluid: SPH (sph_fluid.hpp) has
// particles and no increments; the closed cell of one pressure (cavity_fluid.hpp) has increments and no
// particles, and runs in both schemes. The fluid's state lives in the State (saved by io/state_io.hpp):
// SPH's particles in State::fluid, a closed cell's mass in State::cavity_mass_kg; its rates and scratch
// live in the model.
#include <memory>
#include <type_traits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/energy_terms.hpp"
#include "core/params.hpp"
#include "core/state.hpp"
#include "geometry/neighbours.hpp"
#include "geometry/surface.hpp"
#include "geometry/tissue.hpp"
#include "physics/eos.hpp"

namespace cellsim {

// What a fluid reads of the rest of the step, built by the engine at each call: the equation of state
// at the turgor of the moment, L_p of the stage.
struct FluidContext {
  const WallSurface& surface;
  const NeighbourLists& neighbours;
  const CellRanges& cells;
  EquationOfState eos;
  double Lp_m_per_s_Pa;
  int threads;
};

// What the records read of the fluid (measures.hpp), each the model's own way.
struct FluidReadings {
  double mass_kg = 0;
  double mean_pressure_Pa = 0;     // over the fluid (SPH: the particles' mean)
  double volume_ratio = 0;         // the fluid's own volume / the enclosed volume (every cell's)
  double kinetic_energy_J = 0, max_speed_m_s = 0;
  std::vector<double> cell_mass_kg, cell_mean_pressure_Pa;
};

class FluidModel {
 public:
  virtual ~FluidModel() = default;

  // The fluid of the tissue as built, at rest at rho0 in walls of this surface.
  virtual void fill(State& s, const Tissue& tissue, const WallSurface& surface) const = 0;
  virtual double mass_kg(const State& s) const = 0;
  virtual FluidReadings readings(const State& s, const CellRanges& cells, const WallSurface& surface,
                                 const EquationOfState& eos) const = 0;

  // The cut-off of the wall-fluid pair list at smoothing length h_m (Eq 6), kept for the forces (0: the
  // fluid has no wall pairs).
  virtual double follow_smoothing_length(double h_m) = 0;
  // The methods given power_W write there the powers of their terms of the energy account
  // (core/energy_terms.hpp), which the engine's kicks integrate.
  // The fluid's own forces and rates at the current positions, then Eq 11's mass transfer.
  // pairs_fresh: the density's drift step already went over the fluid's pairs at these positions.
  virtual void compute_forces(State& s, const FluidContext& c, bool pairs_fresh, EnergyValues& power_W) = 0;
  virtual void transfer_mass(State& s, const FluidContext& c, EnergyValues& power_W) = 0;
  // The forces between fluid and wall: on the fluid, its own; on the wall, into on_wall (its share
  // beyond the fluid's pressure, the pressure coupling's backstop, into backstop_on_wall as well).
  // weights_fresh: the density's drift step already weighed the wall pairs at these positions.
  virtual void couple_to_wall(State& s, const FluidContext& c, bool weights_fresh, Eigen::Matrix3Xd& on_wall,
                              Eigen::Matrix3Xd& backstop_on_wall, EnergyValues& power_W) = 0;
  // Its terms of the stored energy: kinetic (the fluid's part), internal (Eq 7), the coupling's potential.
  virtual void stored_energy(const State& s, const FluidContext& c, EnergyValues& e) const = 0;
  // d(stored energy)/d(P_T) at fixed particles: what the drying's turgor ramp does to the account.
  virtual double stored_energy_per_turgor_m3(const State& s, const EquationOfState& eos) const = 0;
  // Per cell, the mean pressure at the last force evaluation.
  virtual std::vector<double> cell_mean_pressure_Pa(const CellRanges& cells) const = 0;
};

class LeapfrogFluid {
 public:
  virtual ~LeapfrogFluid() = default;
  // Half a kick of the fluid's own rates (a particle's velocity, a closed cell's mass).
  virtual void kick(State& s, double half_dt, int threads) = 0;
  // "" if time.dt_ns is within the fluid's limits at this state, else which it exceeds (step_checks.hpp).
  virtual std::string time_step_violation(const State& s, const FluidContext& c) const = 0;
};

class ParticleFluid {
 public:
  virtual ~ParticleFluid() = default;
  // time.density_update = drift: density and mass by dt at the drifted positions, before the forces.
  virtual bool density_in_drift() const = 0;
  virtual void advance_density(State& s, const FluidContext& c, double dt, const EnergyValues& power_W) = 0;
  // A drift of the particles; returns the largest |v|^2 (for the neighbour lists).
  virtual double drift(State& s, double dt, int threads) = 0;
  // The closures of model.md §4-5: drying holds the fluid's pressure to the wall's (per cell), compression
  // holds each cell's fluid volume to its enclosed volume as it was when compression started.
  virtual void apply_drying_closure(State& s, const FluidContext& c, const std::vector<double>& cell_wall_pressure_Pa) = 0;
  virtual void start_compression(State& s, const FluidContext& c) = 0;
  virtual void apply_compression_closure(State& s, const FluidContext& c) = 0;
  // The force on each fluid particle at the last evaluation.
  virtual const Eigen::Matrix3Xd& particle_force() const = 0;
};

class IncrementFluid {
 public:
  virtual ~IncrementFluid() = default;
  // Eq 11 over one increment of dt_s, backward Euler: until end_increment, each cell's density is the one
  // at which its mass now plus dt dM/dt fills the volume its wall encloses (the wall's area and L_p as
  // now). dt_s = infinity: drained, P = P_T; 0: no water moves.
  virtual void begin_increment(const State& s, const FluidContext& c, double dt_s) = 0;
  // Into the state, the masses the increment ends with; returns the energy Eq 11's water brought over it.
  virtual double end_increment(State& s, const FluidContext& c) = 0;
  // In an increment, the fluid's potential: the work the cells' pressures did on their walls since it
  // began, the integral of P dV from each cell's volume then to its volume now (P a function of V there).
  virtual double increment_work_J(const FluidContext& c) const = 0;
  // Per cell, -dP/dV at the last force evaluation (in an increment, Eq 11's backward Euler softens it).
  virtual std::vector<double> volume_stiffness_Pa_m3(const EquationOfState& eos) const = 0;
  // dV/dx of each cell's enclosed volume on its wall particles, stacked (x, y, z per particle) [m^2].
  virtual Eigen::VectorXd volume_gradients(const WallSurface& surface) const = 0;
};

// One fluid model and the faces it has (null where it has none).
struct Fluid {
  std::unique_ptr<FluidModel> model;
  LeapfrogFluid* leapfrog = nullptr;
  ParticleFluid* particles = nullptr;
  IncrementFluid* increments = nullptr;

  template <class Model>
  static Fluid of(std::unique_ptr<Model> m) {
    Fluid f;
    if constexpr (std::is_base_of_v<LeapfrogFluid, Model>) f.leapfrog = m.get();
    if constexpr (std::is_base_of_v<ParticleFluid, Model>) f.particles = m.get();
    if constexpr (std::is_base_of_v<IncrementFluid, Model>) f.increments = m.get();
    f.model = std::move(m);
    return f;
  }
};

}  // namespace cellsim
