#pragma once
// The volume closure of a closed cell (compression.volume_closure_time_us; docs/model-closures.md, "The
// verification ladder"): while the plates press, water hardly crosses the wall (L_p = 1e-12), so the
// fluid's volume must follow the volume its wall encloses. The SPH volume sum m/rho does not quite: where
// the fluid fills less than half of a wall particle's kernel (under the plates, 0.46) the pressure
// coupling's wall term counts less than the volume the wall sweeps, and the fluid's jitter lets its
// density drift at a fixed volume. Each step of the compression, every density of a cell is scaled by
// (y / y0)^(dt / tau), y = sum(m/rho) / V_cell and y0 its value when the compression started, so that the
// ratio relaxes back over tau. The internal energy this changes is a flow of the energy account.
#include <cmath>

#include "core/params.hpp"

namespace cellsim {

// ratio: sum(m/rho) / V_cell now; start_ratio: y0.
inline double volume_closure_factor(double ratio, double start_ratio, double dt_s, double tau_s) {
  if (!(tau_s > 0) || !(ratio > 0) || !(start_ratio > 0)) return 1.0;
  return std::pow(ratio / start_ratio, dt_s / tau_s);
}

// The default: on (1 us) with the pressure coupling, whose wall term is what misses the swept volume; off
// with the paper's Lennard-Jones layer (its study keeps its numbers).
inline void resolve_volume_closure(Params& p) {
  if (!p.volume_closure_time_s) p.volume_closure_time_s = p.coupling_model == kPressure ? 1e-6 : 0.0;
}

}  // namespace cellsim
