#pragma once
// When the leapfrog advances the fluid's density and mass (time.density_update, docs/model.md §7).
// kick: in both half kicks, with the velocity, from the rates of one pass over the pairs. The force of
//   a step then sees a density that has not yet felt the step's half-step velocities, so the acoustic
//   pair (velocity, density) is advanced by a forward-Euler map, which amplifies every mode by
//   sqrt(1 + (omega dt)^2) a step; only the viscosity holds that down. The paper's study runs so
//   (lennard_jones), and its numbers stay those of this scheme.
// drift: with the positions, rho(n+1) = rho(n) + dt d(rho)/dt(x(n+1), v(n+1/2)), before the forces
//   are computed from it (a continuity pass, then a force pass): the acoustic pair is then advanced
//   like position and velocity, a symplectic map, stable for omega dt < 2 without any viscosity.
//   The pressure coupling needs it: its wall term couples the light wall particles to the fluid's
//   density, and under kick its dried cell rang at dt 1 ns (docs/model-closures.md).
#include "core/params.hpp"

namespace cellsim {

inline Choice default_density_update(Choice coupling_model) {
  return coupling_model == kPressure ? kDensityDrift : kDensityKick;
}

// Fills in time.density_update if it is auto.
inline void resolve_density_update(Params& p) {
  if (p.density_update == kDensityAuto) p.density_update = default_density_update(p.coupling_model);
}

}  // namespace cellsim
