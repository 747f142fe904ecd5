#include "physics/wall_stiffness.hpp"

#include <algorithm>
#include <vector>

#include "physics/wall_terms.hpp"

namespace cellsim {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

void add_block(Triplets& entries, Eigen::Index a, Eigen::Index b, const Eigen::Matrix3d& block) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) entries.emplace_back(3 * a + r, 3 * b + c, block(r, c));
}

// [v]x, the cross product with v as a matrix: [v]x w = v x w.
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

}  // namespace

Eigen::SparseMatrix<double> wall_spring_stiffness(const Eigen::Matrix3Xd& x, const WallMesh& mesh, const BondLaw& law,
                                                  double ramp, const PlateLaw& plate_law, const Plates& plates,
                                                  double shift_N_m) {
  const Eigen::Index n = x.cols();
  Triplets entries;
  entries.reserve(mesh.bonds.size() * 36 + static_cast<std::size_t>(3 * n));
  for (std::size_t i = 0; i < mesh.bonds.size(); ++i) {
    const int a = mesh.bonds[i][0], b = mesh.bonds[i][1];
    const Eigen::Vector3d d = x.col(b) - x.col(a);
    const double l = d.norm(), l0 = mesh.rest_length_m[i];
    const Eigen::Vector3d u = d / l;
    const double l_ref = wall::contraction_rest_length(l0, law.contraction_ratio, law.dryness, ramp);
    const double tension = law.G_t_N_m[i] * l0 / std::sqrt(3.0) * (l / l0 - l0 / l) +
                           wall::contraction_tension(law.contraction_N_m, l, l_ref);
    const double along = law.contraction_N_m + wall::stiff_stiffness(law.G_t_N_m[i], l / l0);
    const Eigen::Matrix3d block = along * u * u.transpose() +
                                  std::max(tension, 0.0) / l * (Eigen::Matrix3d::Identity() - u * u.transpose());
    add_block(entries, a, a, block);
    add_block(entries, b, b, block);
    add_block(entries, a, b, -block);
    add_block(entries, b, a, -block);
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    const bool touched = plates.active && plate_overlap(x.col(k), plate_law, plates).touches();
    for (int r = 0; r < 3; ++r) entries.emplace_back(3 * k + r, 3 * k + r, shift_N_m + (touched && r == 2 ? plate_law.stiffness_N_m : 0.0));
  }
  Eigen::SparseMatrix<double> K(3 * n, 3 * n);
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

// V = sum over triangles (a, b, c) of x_a . (x_b x x_c) / 6, so d2V / dx_a dx_b = -[x_c]x / 6 (cyclic), and
// the potential's -P V gives P / 6 [x_c]x; (b, a) is its transpose. A closed surface's sum does not depend
// on the origin: each cell's is taken at its first triangle's first corner, for round-off.
Eigen::SparseMatrix<double> pressure_follower_stiffness(const Eigen::Matrix3Xd& x, const WallMesh& mesh,
                                                        const std::vector<double>& cell_pressure_Pa) {
  Triplets entries;
  entries.reserve(mesh.triangles.size() * 54);
  for (int cell = 0; cell < mesh.cells(); ++cell) {
    const double sixth_P = cell_pressure_Pa[static_cast<std::size_t>(cell)] / 6.0;
    const Eigen::Vector3d origin = x.col(mesh.triangles[static_cast<std::size_t>(mesh.cell_triangles[cell])][0]);
    for (int t = mesh.cell_triangles[cell]; t < mesh.cell_triangles[cell + 1]; ++t) {
      const std::array<int, 3>& corner = mesh.triangles[static_cast<std::size_t>(t)];
      for (int i = 0; i < 3; ++i) {
        const int a = corner[i], b = corner[(i + 1) % 3], c = corner[(i + 2) % 3];
        const Eigen::Matrix3d block = sixth_P * cross_matrix(x.col(c) - origin);
        add_block(entries, a, b, block);
        add_block(entries, b, a, block.transpose());
      }
    }
  }
  Eigen::SparseMatrix<double> K(x.size(), x.size());
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

}  // namespace cellsim
