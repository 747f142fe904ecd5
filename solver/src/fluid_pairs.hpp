#pragma once
// The fluid-fluid pair loop: continuity (Eq 10), pressure (Eq 3) and viscous (Eq 4) terms over
// a half pair list, each pair visited once and applied to both particles.
#include <vector>

#include <Eigen/Core>

#include "eos.hpp"
#include "kernel.hpp"
#include "neighbours.hpp"
#include "state.hpp"

namespace cellsim {

struct FluidRates {
  Eigen::Matrix3Xd force;   // [N]
  Eigen::VectorXd drho_dt;  // continuity part only [kg/m^3/s]
  Eigen::VectorXd pressure; // EOS pressure [Pa]
  // Scratch of the pair loop, kept to avoid reallocation: P/rho^2 and m/rho per particle, and
  // the pairs of the list within the kernel support (compressed rows) with their (1/r) dW/dr.
  Eigen::VectorXd P_over_rho2, volume, pair_g;
  std::vector<int> active_offset, active_index;
};

// Overwrites out (sized to the fluid).
void fluid_pair_terms(const FluidParticles& f, const PairList& pairs, const CubicSplineKernel& kernel,
                      const EquationOfState& eos, double viscosity_Pa_s, FluidRates& out);

}  // namespace cellsim
