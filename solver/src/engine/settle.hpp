#pragma once
// The calm start (docs/model-closures.md, "The start at rest"): before the drying clock starts, the
// fresh cell is relaxed to rest at its fresh turgor, so that no particle is launched at t = 0.
// A FIRE minimisation (Bitzek et al. 2006, Phys. Rev. Lett. 97:170201) in pseudo-time: density
// frozen at rho0 (every particle at P = P_T0, which is where Eq 11 holds it at steady state),
// fluid and wall positions free, and the fluid masses scaled until the wall carries exactly the
// fluid pressure (the target of the wall-pressure closure). Not part of the recorded time series.
// A closed cell (fluid.model = cavity) has no particles to relax: its wall is relaxed under P_T0 held
// (quasi_static.hpp), to time.equilibrium_tolerance, and its mass is then rho0 times its volume.
#include <cstdint>

namespace cellsim {

class Simulation;

struct SettleReport {
  std::int64_t iterations = 0;
  double residual = 0;        // largest fluid acceleration / (P_T0 / (rho0 dx)) at the end (closed cell: quasi_static.hpp's)
  bool converged = false;     // residual <= settle.tolerance
  double mass_ratio = 1;      // fluid mass after / before (the masses the wall-pressure balance asks for)
  double volume_ratio = 1;    // enclosed volume after / before: the fresh cell inflated by its turgor
};

// Relaxes sim's state in place (velocities zero at the end) and restarts its clock at t = 0.
// max_iterations = 0 leaves the cell as built. Throws NumericalFailure if the relaxation pushes a
// fluid particle out of the wall.
SettleReport settle(Simulation& sim, std::int64_t max_iterations, double tolerance);

}  // namespace cellsim
