#pragma once
// Convex hull of points on a sphere, triangulated by Qhull (model.md §1).
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cellsim {

// Triangles (vertex indices into the columns of points), oriented outward from the centroid.
// Throws InputError if Qhull fails or some point is not a hull vertex.
std::vector<std::array<int, 3>> convex_hull_triangles(const Eigen::Matrix3Xd& points);

// The volume of the convex hull of the points (Qhull's), for a tissue's volume (model.md §10).
double convex_hull_volume(const Eigen::Matrix3Xd& points);

// The area of the convex hull of points in a plane (the footprint a tissue or cell presses on a plate).
double convex_hull_area_2d(const Eigen::Matrix2Xd& points);

}  // namespace cellsim
