#include "wall_bonds.hpp"

#include "wall_terms.hpp"

namespace cellsim {

double add_bond_forces(const WallParticles& w, const WallMesh& mesh, const BondLaw& law, double ramp,
                       Eigen::Matrix3Xd& force) {
  double tension_times_length = 0;
  for (std::size_t b = 0; b < mesh.bonds.size(); ++b) {
    const int k = mesh.bonds[b][0], j = mesh.bonds[b][1];
    const Eigen::Vector3d d = w.x.col(j) - w.x.col(k);
    const double l = d.norm();
    const double l0 = mesh.rest_length_m[b];
    const double l_ref = wall::contraction_rest_length(l0, law.contraction_ratio, law.dryness, ramp);
    const double tension =
        wall::stiff_tension(law.G_Pa, law.thickness_m, l0, l) + wall::contraction_tension(law.contraction_N_m, l, l_ref);
    tension_times_length += tension * l;
    const Eigen::Vector3d f_k = tension / l * d + wall::damping_force(law.damping_N_s_m, w.v.col(k), w.v.col(j));
    force.col(k) += f_k;
    force.col(j) -= f_k;
  }
  return tension_times_length;
}

}  // namespace cellsim
