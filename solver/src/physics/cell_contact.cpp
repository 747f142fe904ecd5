#include "physics/cell_contact.hpp"

#include <algorithm>
#include <cmath>

namespace cellsim {

int add_cell_contact_forces(const Eigen::Matrix3Xd& wall_x, const PairList& wall_wall,
                            const std::vector<LamellaBond>& bonds, const CellContactLaw& law,
                            std::vector<char>& intact, std::vector<double>& peak_opening_m,
                            Eigen::Matrix3Xd& wall_force) {
  const double gap2 = law.gap_m * law.gap_m;
  for (int k = 0; k < wall_wall.rows(); ++k)
    for (std::size_t q = static_cast<std::size_t>(wall_wall.offset[static_cast<std::size_t>(k)]);
         q < static_cast<std::size_t>(wall_wall.offset[static_cast<std::size_t>(k) + 1]); ++q) {
      const int l = wall_wall.index[q];
      const Eigen::Vector3d kl = wall_x.col(k) - wall_x.col(l);
      const double r2 = kl.squaredNorm();
      if (r2 >= gap2 || r2 == 0) continue;
      const double r = std::sqrt(r2);
      const Eigen::Vector3d push = law.contact_stiffness_N_m * (law.gap_m - r) / r * kl;  // on k, away from l
      wall_force.col(k) += push;
      wall_force.col(l) -= push;
    }
  int broken = 0;
  for (std::size_t b = 0; b < bonds.size(); ++b) {
    if (!intact[b]) continue;
    const LamellaBond& bond = bonds[b];
    const Eigen::Vector3d ab = wall_x.col(bond.b) - wall_x.col(bond.a);
    const double r = ab.norm();
    const double opening = r - bond.length_m;
    peak_opening_m[b] = std::max(peak_opening_m[b], opening);
    if (law.lamella.separated(peak_opening_m[b])) {
      intact[b] = 0;
      ++broken;
      continue;
    }
    const double tension = law.lamella.tension_N(opening, peak_opening_m[b]);
    const Eigen::Vector3d pull = tension / r * ab;  // on a, toward b
    wall_force.col(bond.a) += pull;
    wall_force.col(bond.b) -= pull;
  }
  return broken;
}

}  // namespace cellsim
