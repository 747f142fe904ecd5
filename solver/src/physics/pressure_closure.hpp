#pragma once
// The wall-pressure closure (docs/model-closures.md, model.md §5): during drying, every fluid mass
// is scaled each step by (P_wall / P_mean)^(-dt / 2 tau), density unchanged, so that the pressure
// the wall carries relaxes to the mean fluid pressure (the push on the wall scales as m^2, hence the
// 2). The ratio is clamped to [1/2, 2] so one wild step cannot rescale the fluid by much; without
// turgor on either side there is nothing to match and the factor is 1.
#include <algorithm>
#include <cmath>

namespace cellsim {

inline double pressure_closure_factor(double wall_pressure_Pa, double mean_pressure_Pa, double dt_s, double tau_s) {
  if (tau_s <= 0 || !(mean_pressure_Pa > 0) || !(wall_pressure_Pa > 0)) return 1.0;
  const double ratio = std::clamp(wall_pressure_Pa / mean_pressure_Pa, 0.5, 2.0);
  return std::pow(ratio, -dt_s / (2.0 * tau_s));
}

}  // namespace cellsim
