#pragma once
// Is every fluid particle inside the closed wall? A vertical ray from each particle crosses the
// wall surface an odd number of times exactly when the particle is inside (model.md §4 asks for
// this check at every record). Triangles are binned by their xy footprint, so the test is cheap.
#include <Eigen/Core>

#include "wall_mesh.hpp"

namespace cellsim {

// Index of the first fluid particle outside the wall, or -1 if all are inside.
int first_particle_outside(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const WallMesh& mesh);

}  // namespace cellsim
