#pragma once
// The wall-fluid pair loop: Lennard-Jones coupling (Eqs 12-13, 17-19) between every fluid
// particle and the wall particles near it, equal and opposite.
#include <Eigen/Core>

#include "lennard_jones.hpp"
#include "neighbours.hpp"

namespace cellsim {

// Adds the LJ forces on the fluid to fluid_force and writes those on the wall to on_wall
// (overwritten), which the caller adds to the wall forces and uses for the wall pressure.
// pair_f is scratch (kept by the caller to avoid reallocation): f(r) of every listed pair.
void wall_fluid_forces(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const PairList& pairs,
                       const LennardJones& lj, Eigen::Matrix3Xd& fluid_force, Eigen::Matrix3Xd& on_wall,
                       Eigen::VectorXd& pair_f);

}  // namespace cellsim
