#include "physics/cell_contact.hpp"

#include <algorithm>
#include <cmath>

namespace cellsim {
namespace {

// The loops, with the virial only where it is asked for: a product kept for the virial changes how the
// compiler may fuse the force sums, and a cluster's forces keep their bits without it.
template <bool kVirial>
int contact_forces(const Eigen::Matrix3Xd& wall_x, const PairList& wall_wall, const std::vector<LamellaBond>& bonds,
                   const CellContactLaw& law, const PeriodicBox& box, std::vector<char>& intact,
                   std::vector<double>& peak_opening_m, Eigen::Matrix3Xd& wall_force, Eigen::Vector2d& virial) {
  const double gap2 = law.gap_m * law.gap_m;
  // The period shift of the pair (k, l) (nearest image of k - l, less k - l) times the force on k.
  const auto add_virial = [&](Eigen::Index k, Eigen::Index l, const Eigen::Vector3d& k_minus_l,
                              const Eigen::Vector3d& force_on_k) {
    if constexpr (!kVirial) return;
    const Eigen::Vector3d shift = k_minus_l - (wall_x.col(k) - wall_x.col(l));
    virial += shift.head<2>().cwiseProduct(force_on_k.head<2>());
  };
  for (int k = 0; k < wall_wall.rows(); ++k)
    for (std::size_t q = static_cast<std::size_t>(wall_wall.offset[static_cast<std::size_t>(k)]);
         q < static_cast<std::size_t>(wall_wall.offset[static_cast<std::size_t>(k) + 1]); ++q) {
      const int l = wall_wall.index[q];
      const Eigen::Vector3d kl = box.nearest_image(wall_x.col(k) - wall_x.col(l));
      const double r2 = kl.squaredNorm();
      if (r2 >= gap2 || r2 == 0) continue;
      const double r = std::sqrt(r2);
      const Eigen::Vector3d push = law.contact_stiffness_N_m * (law.gap_m - r) / r * kl;  // on k, away from l
      wall_force.col(k) += push;
      wall_force.col(l) -= push;
      add_virial(k, l, kl, push);
    }
  int broken = 0;
  for (std::size_t b = 0; b < bonds.size(); ++b) {
    if (!intact[b]) continue;
    const LamellaBond& bond = bonds[b];
    const Eigen::Vector3d ab = box.nearest_image(wall_x.col(bond.b) - wall_x.col(bond.a));
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
    add_virial(bond.a, bond.b, -ab, pull);
  }
  return broken;
}

// A pair's stiffness, along n (unit) and across it.
void add_pair_block(int a, int b, const Eigen::Vector3d& n, double along_N_m, double across_N_m, BlockStiffness& K) {
  const Eigen::Matrix3d nn = n * n.transpose();
  K.add_pair(a, b, along_N_m * nn + across_N_m * (Eigen::Matrix3d::Identity() - nn));
}

}  // namespace

int add_cell_contact_forces(const Eigen::Matrix3Xd& wall_x, const PairList& wall_wall,
                            const std::vector<LamellaBond>& bonds, const CellContactLaw& law, const PeriodicBox& box,
                            std::vector<char>& intact, std::vector<double>& peak_opening_m,
                            Eigen::Matrix3Xd& wall_force, Eigen::Vector2d* period_virial_J) {
  Eigen::Vector2d virial = Eigen::Vector2d::Zero();
  const bool with_virial = period_virial_J && box.periodic();
  const int broken = with_virial ? contact_forces<true>(wall_x, wall_wall, bonds, law, box, intact, peak_opening_m,
                                                        wall_force, virial)
                                 : contact_forces<false>(wall_x, wall_wall, bonds, law, box, intact, peak_opening_m,
                                                         wall_force, virial);
  if (period_virial_J) *period_virial_J = virial;
  return broken;
}

int add_cell_contact_stiffness(const Eigen::Matrix3Xd& wall_x, const PairList& wall_wall,
                               const std::vector<LamellaBond>& bonds, const CellContactLaw& law,
                               const PeriodicBox& box, const std::vector<char>& intact,
                               const std::vector<double>& peak_opening_m, BlockStiffness& K) {
  int left_out = 0;
  for (int k = 0; k < wall_wall.rows(); ++k)
    for (std::size_t q = static_cast<std::size_t>(wall_wall.offset[static_cast<std::size_t>(k)]);
         q < static_cast<std::size_t>(wall_wall.offset[static_cast<std::size_t>(k) + 1]); ++q) {
      const int l = wall_wall.index[q];
      const Eigen::Vector3d kl = box.nearest_image(wall_x.col(k) - wall_x.col(l));
      const double r = kl.norm();
      if (r >= law.gap_m || r == 0) continue;
      if (!K.joins(k, l)) {
        ++left_out;
        continue;
      }
      add_pair_block(k, l, kl / r, law.contact_stiffness_N_m, 0.0, K);
    }
  for (std::size_t b = 0; b < bonds.size(); ++b) {
    if (!intact[b]) continue;
    const LamellaBond& bond = bonds[b];
    if (!K.joins(bond.a, bond.b)) {
      ++left_out;
      continue;
    }
    const Eigen::Vector3d ab = box.nearest_image(wall_x.col(bond.b) - wall_x.col(bond.a));
    const double r = ab.norm();
    const double opening = r - bond.length_m, peak = peak_opening_m[b];
    const double tension = law.lamella.tension_N(opening, peak);
    // Every branch of the law is linear through the origin at a fixed history (lamella_law.hpp): its
    // slope is the tension over the opening, the elastic k where the bond is closed or undamaged.
    const bool elastic = opening <= 0 || peak <= law.lamella.elastic_limit_m();
    const double along = elastic ? law.lamella.stiffness_N_m : tension / opening;
    add_pair_block(bond.a, bond.b, ab / r, along, std::max(tension, 0.0) / r, K);
  }
  return left_out;
}

CellContactEnergy cell_contact_energy(const Eigen::Matrix3Xd& wall_x, const PairList& wall_wall,
                                      const std::vector<LamellaBond>& bonds, const CellContactLaw& law,
                                      const PeriodicBox& box, const std::vector<char>& intact,
                                      const std::vector<double>& peak_opening_m) {
  CellContactEnergy e;
  for (int k = 0; k < wall_wall.rows(); ++k)
    for (std::size_t q = static_cast<std::size_t>(wall_wall.offset[static_cast<std::size_t>(k)]);
         q < static_cast<std::size_t>(wall_wall.offset[static_cast<std::size_t>(k) + 1]); ++q) {
      const double r = box.nearest_image(wall_x.col(k) - wall_x.col(wall_wall.index[q])).norm();
      if (r < law.gap_m && r > 0) e.contact_J += 0.5 * law.contact_stiffness_N_m * (law.gap_m - r) * (law.gap_m - r);
    }
  for (std::size_t b = 0; b < bonds.size(); ++b) {
    e.lamella_dissipated_J += law.lamella.dissipated_energy_J(peak_opening_m[b]);
    if (!intact[b]) continue;
    const double r = box.nearest_image(wall_x.col(bonds[b].b) - wall_x.col(bonds[b].a)).norm();
    e.lamella_J += law.lamella.stored_energy_J(r - bonds[b].length_m, peak_opening_m[b]);
  }
  return e;
}

}  // namespace cellsim
