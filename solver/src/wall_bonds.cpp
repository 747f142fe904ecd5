#include "wall_bonds.hpp"

#include <cmath>

#include "wall_terms.hpp"

namespace cellsim {

// Pass 1 gathers squared bond lengths; pass 2 turns them into tension / length over the flat
// array (vectorised: it holds the square roots and divisions); pass 3 applies the forces.
double add_bond_forces(const WallParticles& w, const WallMesh& mesh, const BondLaw& law, double ramp,
                       Eigen::Matrix3Xd& force, Eigen::VectorXd& tension_over_length) {
  const auto n_bonds = static_cast<Eigen::Index>(mesh.bonds.size());
  tension_over_length.resize(n_bonds);
  double* t_over_l = tension_over_length.data();
  for (Eigen::Index b = 0; b < n_bonds; ++b) {
    const auto& bond = mesh.bonds[static_cast<std::size_t>(b)];
    t_over_l[b] = (w.x.col(bond[1]) - w.x.col(bond[0])).squaredNorm();
  }
  const double* rest = mesh.rest_length_m.data();
  for (Eigen::Index b = 0; b < n_bonds; ++b) {
    const double l = std::sqrt(t_over_l[b]);
    const double l_ref = wall::contraction_rest_length(rest[b], law.contraction_ratio, law.dryness, ramp);
    const double tension = wall::stiff_tension(law.G_Pa, law.thickness_m, rest[b], l) +
                           wall::contraction_tension(law.contraction_N_m, l, l_ref);
    t_over_l[b] = tension / l;
  }
  double tension_times_length = 0;
  for (Eigen::Index b = 0; b < n_bonds; ++b) {
    const int k = mesh.bonds[static_cast<std::size_t>(b)][0], j = mesh.bonds[static_cast<std::size_t>(b)][1];
    const Eigen::Vector3d d = w.x.col(j) - w.x.col(k);
    tension_times_length += t_over_l[b] * d.squaredNorm();
    const Eigen::Vector3d f_k = t_over_l[b] * d + wall::damping_force(law.damping_N_s_m, w.v.col(k), w.v.col(j));
    force.col(k) += f_k;
    force.col(j) -= f_k;
  }
  return tension_times_length;
}

}  // namespace cellsim
