#pragma once
// The tests' box of fluid: particles on a jittered cubic lattice, with random velocities and unequal
// densities (so unequal pressures). Shared by the conservation and neighbour-list tests.
#include <cmath>
#include <random>

#include "core/state.hpp"

namespace cellsim::testing {

inline FluidParticles fluid_box(int n_side, double dx, unsigned seed) {
  FluidParticles f;
  const int n = n_side * n_side * n_side;
  f.x.resize(3, n);
  f.v.resize(3, n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.1 * dx, 0.1 * dx), speed(-0.5, 0.5);
  int p = 0;
  for (int i = 0; i < n_side; ++i)
    for (int j = 0; j < n_side; ++j)
      for (int k = 0; k < n_side; ++k, ++p) {
        f.x.col(p) << i * dx + jitter(rng), j * dx + jitter(rng), k * dx + jitter(rng);
        f.v.col(p) << speed(rng), speed(rng), speed(rng);
      }
  f.m = Eigen::VectorXd::Constant(n, 1000.0 * dx * dx * dx);
  f.rho = Eigen::VectorXd::Constant(n, 1000.0);
  for (int q = 0; q < n; ++q) f.rho[q] += 3.0 * std::sin(q);  // unequal pressures
  return f;
}

}  // namespace cellsim::testing
