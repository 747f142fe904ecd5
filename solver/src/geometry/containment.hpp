#pragma once
// Is a point inside a cell's closed wall? A vertical ray from the point crosses the wall surface an
// odd number of times exactly when it is inside (model.md §4 asks for this check of every fluid
// particle at every record; model.md §10 adds that no wall particle may be inside another cell).
// Triangles are binned by their xy footprint, so each test is cheap.
#include <vector>

#include <Eigen/Core>

#include "geometry/wall_mesh.hpp"

namespace cellsim {

class ClosedSurface {
 public:
  // The closed surface of cell `cell` of the mesh, at positions wall_x.
  ClosedSurface(const Eigen::Matrix3Xd& wall_x, const WallMesh& mesh, int cell);
  bool contains(const Eigen::Vector3d& p) const;
  bool box_overlaps(const ClosedSurface& other) const;

 private:
  int bin_of(double v, int d) const;
  const Eigen::Matrix3Xd& wall_x_;
  const WallMesh& mesh_;
  Eigen::Vector3d lo_, hi_;  // bounding box
  int bins_;
  std::vector<std::vector<int>> bin_triangles_;
};

// Index of the first of points [begin, end) outside cell `cell`'s wall, or -1 if all are inside.
int first_particle_outside(const Eigen::Matrix3Xd& points, Eigen::Index begin, Eigen::Index end,
                           const ClosedSurface& wall);

// The single cell's check: the first fluid particle outside the wall (of a one-cell mesh), or -1.
int first_particle_outside(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const WallMesh& mesh);

}  // namespace cellsim
