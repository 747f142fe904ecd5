#pragma once
// The closed wall surface, measured once a step (model.md §1, §8): each triangle's area normal,
// the wall area A_c (Eq 11), the enclosed volume and its equivalent diameter D (Eq 6), and the
// vertex normals and areas. Every user (dynamics, bending, records, settle) reads these numbers.
#include <vector>

#include <Eigen/Core>

#include "parallel/owned_spans.hpp"

#include "geometry/wall_mesh.hpp"

namespace cellsim {

// Per-triangle area normals N = (v - u) x (w - u), |N| (twice the area) and 1/|N|.
struct TriangleNormals {
  Eigen::Matrix3Xd N;
  Eigen::VectorXd norm, inv_norm;
};
void compute_triangle_normals(const Eigen::Matrix3Xd& x, const WallMesh& mesh, TriangleNormals& out, int threads = 1);

struct WallSurface {
  TriangleNormals triangles;
  Eigen::Matrix3Xd vertex_normal;  // sum of the adjacent triangles' area normals (outward)
  double area_m2 = 0;              // sum of the triangles' areas (every cell's)
  double volume_m3 = 0;            // sum of the signed tetrahedra (origin, triangle): > 0 when closed and outward
  std::vector<double> cell_area_m2, cell_volume_m3;  // the same for each cell's closed surface

  // threads: as `cellsim run --threads` (owned_spans.hpp).
  void update(const Eigen::Matrix3Xd& x, const WallMesh& mesh, int threads = 1);
  // The area each wall particle owns: a third of each adjacent triangle's (the contact area, model.md §8).
  Eigen::VectorXd vertex_areas(const WallMesh& mesh) const;

 private:
  std::vector<double> six_volume_;  // per thread and cell (thread t, cell c at t * cells + c), added in thread order
  OwnedSpans spans_;                // each thread's particles and the triangles at them (owned_spans.hpp)
};

WallSurface wall_surface(const Eigen::Matrix3Xd& x, const WallMesh& mesh);

// D of Eq 6: the diameter of the sphere of volume V (V > 0; Simulation stops the run otherwise).
double equivalent_diameter_m(double volume_m3);

}  // namespace cellsim
