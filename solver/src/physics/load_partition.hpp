#pragma once
// How the top plate's load reaches it (model.md §8): the wall particles touching the top plate are
// held by the plate (Eq 22) against the fluid's push on them (the wall-fluid coupling) and the
// wall's own forces (bonds, Eqs 15, 16, 21; bending, Eq 20). At rest the plate force is the sum of
// the two; what is left is the touching particles' inertia.
#include <Eigen/Core>

#include "physics/plates.hpp"

namespace cellsim {

struct LoadPartition {
  double fluid_push_N = 0;  // upward coupling force of the fluid on the wall particles Eq 22 pushes from the top plate
  double wall_push_N = 0;   // upward bond + bending + damping force on them
  double backstop_push_N = 0;  // the part of fluid_push_N the pressure coupling's backstop gives
};

// wall_force: every force on the wall particles at the current state (coupling and plates included);
// coupling_on_wall: the part of it from the fluid; backstop_on_wall: the backstop's part of that (empty
// without one).
LoadPartition top_plate_load(const Eigen::Matrix3Xd& wall_x, const Eigen::Matrix3Xd& wall_force,
                             const Eigen::Matrix3Xd& coupling_on_wall, const Eigen::Matrix3Xd& backstop_on_wall,
                             const PlateLaw& law, const Plates& plates);

}  // namespace cellsim
