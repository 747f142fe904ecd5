#include "geometry/wall_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include <Eigen/Geometry>

#include "core/errors.hpp"

namespace cellsim {

// The spiral's two poles carry its largest, least regular triangles, where the LJ barrier against
// the fluid is weakest (model.md §4). The default axis lies in the equatorial plane, 1 rad from x: away
// from the plates (which load the wall-fluid layer most) and from every row of the cubic fluid lattice
// (a row ending under a pole triangle put a fluid particle right over its centre, and it leaked).
Eigen::Vector3d default_spiral_axis() { return Eigen::Vector3d(std::cos(1.0), std::sin(1.0), 0.0); }

Eigen::Matrix3Xd fibonacci_sphere(int n, double radius, const Eigen::Vector3d& axis) {
  // e1, e2 span the plane normal to the axis; e1 is z (or x for an axis near z) made normal to it.
  const Eigen::Vector3d reference = std::abs(axis.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d e1 = (reference - reference.dot(axis) * axis).normalized();
  const Eigen::Vector3d e2 = axis.cross(e1);
  Eigen::Matrix3Xd x(3, n);
  const double golden_angle = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden_angle * i;
    x.col(i) = radius * (r * std::cos(phi) * e1 + r * std::sin(phi) * e2 + z * axis);
  }
  return x;
}

WallMesh build_wall_mesh(const Eigen::Matrix3Xd& positions, std::vector<std::array<int, 3>> triangles) {
  // Triangles in memory order (each rotated to start at its smallest vertex, which keeps its
  // orientation, then sorted), so the loops over triangles and hinges walk the wall particles in
  // order rather than in the hull's construction order.
  for (auto& t : triangles) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(triangles.begin(), triangles.end());
  WallMesh mesh;
  // Each directed edge (u -> v) of an outward triangle; its twin (v -> u) lives in the neighbour.
  // directed edge -> (vertex opposite it, triangle index)
  std::map<std::pair<int, int>, std::pair<int, int>> opposite;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int e = 0; e < 3; ++e) {
      const auto& tri = triangles[t];
      const int u = tri[e], v = tri[(e + 1) % 3], w = tri[(e + 2) % 3];
      if (!opposite.emplace(std::make_pair(u, v), std::make_pair(w, static_cast<int>(t))).second)
        throw InputError("wall triangulation is not a closed oriented surface (edge " + std::to_string(u) + "-" +
                         std::to_string(v) + " appears twice)");
    }
  for (const auto& [edge, near] : opposite) {
    const auto [a, b] = edge;
    if (a > b) continue;  // visit each undirected edge once, from its (small, large) direction
    const auto twin = opposite.find({b, a});
    if (twin == opposite.end())
      throw InputError("wall triangulation has an open edge " + std::to_string(a) + "-" + std::to_string(b));
    mesh.bonds.push_back({a, b});
    mesh.rest_length_m.push_back((positions.col(a) - positions.col(b)).norm());
    mesh.hinges.push_back({a, b, near.first, twin->second.first, near.second, twin->second.second});
  }
  mesh.triangles = std::move(triangles);
  mesh.cell_triangles = {0, static_cast<int>(mesh.triangles.size())};
  return mesh;
}

double largest_circumradius(const Eigen::Matrix3Xd& x, const std::vector<std::array<int, 3>>& triangles) {
  double largest = 0;
  for (const auto& t : triangles) {
    const double a = (x.col(t[1]) - x.col(t[2])).norm(), b = (x.col(t[0]) - x.col(t[2])).norm(),
                 c = (x.col(t[0]) - x.col(t[1])).norm();
    const double twice_area = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0])).norm();
    largest = std::max(largest, a * b * c / (2.0 * twice_area));
  }
  return largest;
}

}  // namespace cellsim
