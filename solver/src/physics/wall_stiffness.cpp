#include "physics/wall_stiffness.hpp"

#include <algorithm>
#include <vector>

#include "physics/wall_terms.hpp"

namespace cellsim {

Eigen::SparseMatrix<double> wall_spring_stiffness(const Eigen::Matrix3Xd& x, const WallMesh& mesh, const BondLaw& law,
                                                  double ramp, const PlateLaw& plate_law, const Plates& plates,
                                                  double shift_N_m) {
  const Eigen::Index n = x.cols();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(mesh.bonds.size() * 36 + static_cast<std::size_t>(3 * n));
  const auto add_block = [&](Eigen::Index a, Eigen::Index b, const Eigen::Matrix3d& block) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) entries.emplace_back(3 * a + r, 3 * b + c, block(r, c));
  };
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
    add_block(a, a, block);
    add_block(b, b, block);
    add_block(a, b, -block);
    add_block(b, a, -block);
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    const bool touched = plates.active && plate_overlap(x.col(k), plate_law, plates).touches();
    for (int r = 0; r < 3; ++r) entries.emplace_back(3 * k + r, 3 * k + r, shift_N_m + (touched && r == 2 ? plate_law.stiffness_N_m : 0.0));
  }
  Eigen::SparseMatrix<double> K(3 * n, 3 * n);
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

}  // namespace cellsim
