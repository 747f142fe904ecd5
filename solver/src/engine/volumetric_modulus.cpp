// The cell's volumetric elastic modulus (volumetric_modulus.hpp).
#include "engine/volumetric_modulus.hpp"

#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "engine/quasi_static.hpp"
#include "engine/simulation.hpp"

namespace cellsim {
namespace {

constexpr double kToleranceShare = 1e-2;  // of time.equilibrium_tolerance: the difference needs the digits

struct PressureVolume {
  double pressure_Pa, volume_m3;
};

// The cells' mean pressure and volume at equilibrium with each mass scaled by `scale`, the mass kept.
PressureVolume relaxed_with_mass(Simulation& sim, IncrementFluid& increments, double scale) {
  State& s = sim.mutable_state();
  for (double& mass : s.cavity_mass_kg) mass *= scale;
  sim.refresh_rates();
  increments.begin_increment(s, sim.fluid_context(), 0.0);  // dt = 0: Eq 11 moves no water
  const Equilibrium eq = relax_wall(sim, increments, kToleranceShare * sim.params().equilibrium_tolerance,
                                    sim.params().relaxation_max_iterations);
  increments.end_increment(s, sim.fluid_context());
  if (!eq.converged) {
    std::ostringstream msg;
    msg << "the volumetric modulus: the wall with its water x " << scale << " did not reach equilibrium within "
        << "time.relaxation_max_iterations = " << sim.params().relaxation_max_iterations << " (largest force " << eq.residual
        << " of its pressure load)";
    throw NumericalFailure(msg.str());
  }
  sim.refresh_rates();
  const Record r = sim.record();
  return {r.mean_pressure_Pa, r.volume_m3};
}

}  // namespace

double volumetric_modulus_Pa(Simulation& sim) {
  IncrementFluid* increments = sim.fluid_increments();  // the closed cell's: SPH's has no equilibrium to probe
  if (!increments) return std::nan("");
  const State saved = sim.state();
  const PressureVolume more = relaxed_with_mass(sim, *increments, 1 + kMassStep);
  sim.restore(saved);
  const PressureVolume less = relaxed_with_mass(sim, *increments, 1 - kMassStep);
  sim.restore(saved);
  const double volume_m3 = sim.surface().volume_m3;
  return volume_m3 * (more.pressure_Pa - less.pressure_Pa) / (more.volume_m3 - less.volume_m3);
}

}  // namespace cellsim
