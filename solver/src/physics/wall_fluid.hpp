#pragma once
// The wall-fluid pair loop: Lennard-Jones coupling (Eqs 12-13, 17-19) between every fluid
// particle and the wall particles near it, equal and opposite.
#include <Eigen/Core>

#include "geometry/neighbours.hpp"
#include "parallel/block_sums.hpp"
#include "physics/lennard_jones.hpp"

namespace cellsim {

// Kept by the caller between steps, so that no step allocates.
struct WallFluidScratch {
  Eigen::VectorXd pair_f;                // f(r) of every listed pair
  BlockSums<Eigen::Matrix3Xd> sums;      // per-thread forces on the wall (block_sums.hpp)
};

// Adds the LJ forces on the fluid to fluid_force and writes those on the wall to on_wall
// (overwritten), which the caller adds to the wall forces and uses for the wall pressure.
void wall_fluid_forces(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const PairList& pairs,
                       const LennardJones& lj, int threads, Eigen::Matrix3Xd& fluid_force, Eigen::Matrix3Xd& on_wall,
                       WallFluidScratch& scratch);

}  // namespace cellsim
