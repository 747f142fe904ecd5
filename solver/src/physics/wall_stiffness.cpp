#include "physics/wall_stiffness.hpp"

#include <algorithm>

#include "physics/wall_terms.hpp"

namespace cellsim {
namespace {

// [v]x, the cross product with v as a matrix: [v]x w = v x w.
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

}  // namespace

void add_wall_spring_stiffness(const Eigen::Matrix3Xd& x, const WallMesh& mesh, const BondLaw& law, double ramp,
                               const std::vector<double>& plastic_elongation_m, const PlateLaw& plate_law,
                               const Plates& plates, double shift_N_m, BlockStiffness& K) {
  for (std::size_t i = 0; i < mesh.bonds.size(); ++i) {
    const int a = mesh.bonds[i][0], b = mesh.bonds[i][1];
    const Eigen::Vector3d d = x.col(b) - x.col(a);
    // The springs stretch by the bond's length less its slider's elongation (wall_plasticity.hpp); the
    // tension turns with the bond of length l.
    const double l = d.norm(), l0 = mesh.rest_length_m[i], l_e = l - plastic_elongation_m[i];
    const Eigen::Vector3d u = d / l;
    const double l_ref = wall::contraction_rest_length(l0, law.contraction_ratio, law.dryness, ramp);
    const double tension = law.G_t_N_m[i] * l0 / std::sqrt(3.0) * (l_e / l0 - l0 / l_e) +
                           wall::contraction_tension(law.contraction_N_m, l_e, l_ref);
    const double along = law.contraction_N_m + wall::stiff_stiffness(law.G_t_N_m[i], l_e / l0);
    const Eigen::Matrix3d block = along * u * u.transpose() +
                                  std::max(tension, 0.0) / l * (Eigen::Matrix3d::Identity() - u * u.transpose());
    K.add_pair(a, b, block);
  }
  for (int k = 0; k < static_cast<int>(x.cols()); ++k) {
    const bool touched = plates.active && plate_overlap(x.col(k), plate_law, plates).touches();
    const Eigen::Vector3d diagonal(shift_N_m, shift_N_m, shift_N_m + (touched ? plate_law.stiffness_N_m : 0.0));
    K.add(k, k, diagonal.asDiagonal().toDenseMatrix());
  }
}

// V = sum over triangles (a, b, c) of x_a . (x_b x x_c) / 6, so d2V / dx_a dx_b = -[x_c]x / 6 (cyclic), and
// the potential's -P V gives P / 6 [x_c]x; (b, a) is its transpose. A closed surface's sum does not depend
// on the origin: each cell's is taken at its first triangle's first corner, for round-off.
void add_pressure_follower_stiffness(const Eigen::Matrix3Xd& x, const WallMesh& mesh,
                                     const std::vector<double>& cell_pressure_Pa, BlockStiffness& K) {
  for (int cell = 0; cell < mesh.cells(); ++cell) {
    const double sixth_P = cell_pressure_Pa[static_cast<std::size_t>(cell)] / 6.0;
    const Eigen::Vector3d origin = x.col(mesh.triangles[static_cast<std::size_t>(mesh.cell_triangles[cell])][0]);
    for (int t = mesh.cell_triangles[cell]; t < mesh.cell_triangles[cell + 1]; ++t) {
      const std::array<int, 3>& corner = mesh.triangles[static_cast<std::size_t>(t)];
      for (int i = 0; i < 3; ++i) {
        const int a = corner[i], b = corner[(i + 1) % 3], c = corner[(i + 2) % 3];
        const Eigen::Matrix3d block = sixth_P * cross_matrix(x.col(c) - origin);
        K.add(a, b, block);
        K.add(b, a, block.transpose());
      }
    }
  }
}

}  // namespace cellsim
