#pragma once
// The quasi-static scheme (time.scheme = quasi_static; a cavity fluid: cavity_fluid.hpp): each step of
// time.dt_ns moves the loads at fixed particles (the plates, the drying ramp), integrates Eq 11 over it
// (backward Euler, one mass per cell), and relaxes the wall to equilibrium under them. The plates'
// speed and L_p keep their meaning: a step is dt of physical time, a sequence of equilibria.
//
// The relaxation is FIRE (Bitzek et al. 2006, Phys. Rev. Lett. 97:170201) on the wall positions with
// the wall's masses, its pseudo-step from the wall springs' stability limit. Equilibrium: the largest
// force on a wall particle below time.equilibrium_tolerance x its pressure load, max(P_T0, |P|) x the
// mean area a wall particle owns; its velocities are then zero.
//
// The energy account: the loads' moves are jumps at fixed particles (plate work: the plates' springs;
// drive: P_T and L_ref), Eq 11's water a jump per step (cavity_fluid.hpp), and the relaxation's losses
// (FIRE's steering and stops, the wall damping at pseudo-velocities, the kinetic energy left at
// equilibrium) are measured as they happen: the residual is the relaxation's integration error.
#include <cstdint>

namespace cellsim {

class Simulation;

struct Equilibrium {
  std::int64_t iterations = 0;
  double residual = 0;   // largest force on a wall particle / its pressure load, at the end
  bool converged = false;
  double loss_J = 0;     // energy the relaxation took out
};

// Relaxes the wall of sim in place to equilibrium under its loads now, within max_iterations.
Equilibrium relax_wall(Simulation& sim, double tolerance, std::int64_t max_iterations);

// One quasi-static step. Throws NumericalFailure (naming the step) if the wall does not reach
// equilibrium within time.relaxation_max_iterations.
void quasi_static_step(Simulation& sim);

}  // namespace cellsim
