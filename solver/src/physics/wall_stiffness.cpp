#include "physics/wall_stiffness.hpp"

#include <algorithm>
#include <cmath>

#include "physics/wall_terms.hpp"

namespace cellsim {

void add_wall_spring_stiffness(const Eigen::Matrix3Xd& x, const WallMesh& mesh, const BondLaw& law, double ramp,
                               const std::vector<double>& plastic_elongation_m, BlockStiffness& K) {
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
}

}  // namespace cellsim
