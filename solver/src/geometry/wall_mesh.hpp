#pragma once
// The wall's triangle network: triangles, bonds (edges) with rest lengths, bending hinges.
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace cellsim {

// Two triangles sharing edge (a, b): (a, b, c) and (b, a, d), both outward (Eq 20); t1 and t2
// are their indices in WallMesh::triangles (same normals: cyclic order is kept).
struct Hinge {
  int a, b, c, d;
  int t1, t2;
};

struct WallMesh {
  std::vector<std::array<int, 3>> triangles;  // outward
  std::vector<std::array<int, 2>> bonds;      // i < j, each edge once
  std::vector<double> rest_length_m;          // l0 per bond (initial edge length)
  std::vector<Hinge> hinges;                  // one per interior edge (all edges of a closed surface)
  // One closed surface per cell: cell c's triangles are [cell_triangles[c], cell_triangles[c + 1]).
  std::vector<int> cell_triangles;
  int cells() const { return static_cast<int>(cell_triangles.size()) - 1; }
};

// Builds bonds and hinges from outward triangles; throws InputError if the surface is not closed.
WallMesh build_wall_mesh(const Eigen::Matrix3Xd& positions, std::vector<std::array<int, 3>> triangles);

// The spiral's default axis: in the equatorial plane, 1 rad from x (wall_mesh.cpp says why).
Eigen::Vector3d default_spiral_axis();

// Points on a sphere by the golden-spiral (Fibonacci) lattice around `axis` (a unit vector):
// quasi-uniform, deterministic; its two poles, on the axis, carry the least regular triangles.
Eigen::Matrix3Xd fibonacci_sphere(int n, double radius, const Eigen::Vector3d& axis = default_spiral_axis());

double largest_circumradius(const Eigen::Matrix3Xd& positions, const std::vector<std::array<int, 3>>& triangles);

}  // namespace cellsim
