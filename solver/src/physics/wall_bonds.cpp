#include "physics/wall_bonds.hpp"

#include <cmath>

#include "parallel/threads.hpp"
#include "physics/wall_terms.hpp"

namespace cellsim {

namespace {

// The per-block loops are functions of their own, with the scalars as value parameters: inside a
// lambda that is also handed to other threads they would be re-read after every store.

// Passes 1 and 2 for bonds [begin, end): squared lengths, then tension / length over the flat array
// (vectorised: it holds the square roots and divisions).
void tension_over_length(const WallParticles& w, const WallMesh& mesh, const BondLaw& law, double ramp,
                         Eigen::Index begin, Eigen::Index end, double* t_over_l) {
  for (Eigen::Index b = begin; b < end; ++b) {
    const auto& bond = mesh.bonds[static_cast<std::size_t>(b)];
    t_over_l[b] = (w.x.col(bond[1]) - w.x.col(bond[0])).squaredNorm();
  }
  const double* rest = mesh.rest_length_m.data();
  for (Eigen::Index b = begin; b < end; ++b) {
    const double l = std::sqrt(t_over_l[b]);
    const double l_ref = wall::contraction_rest_length(rest[b], law.contraction_ratio, law.dryness, ramp);
    const double tension = wall::stiff_tension(law.G_Pa, law.thickness_m, rest[b], l) +
                           wall::contraction_tension(law.contraction_N_m, l, l_ref);
    t_over_l[b] = tension / l;
  }
}

// Pass 3: the forces of the span's bonds on the ends it owns; returns the tension x length of the
// bonds whose first end it owns (each bond counted once).
template <class All>
double apply_bonds(All, const WallParticles& w, const WallMesh& mesh, double damping_N_s_m, const double* t_over_l,
                   const OwnedSpan& span, Eigen::Matrix3Xd& force) {
  double tension_times_length = 0;
  for (Eigen::Index b = span.item_begin; b < span.item_end; ++b) {
    const int k = mesh.bonds[static_cast<std::size_t>(b)][0], j = mesh.bonds[static_cast<std::size_t>(b)][1];
    const bool owns_k = All::value || span.owns(k), owns_j = All::value || span.owns(j);
    if (!owns_k && !owns_j) continue;
    const Eigen::Vector3d d = w.x.col(j) - w.x.col(k);
    if (owns_k) tension_times_length += t_over_l[b] * d.squaredNorm();
    const Eigen::Vector3d f_k = t_over_l[b] * d + wall::damping_force(damping_N_s_m, w.v.col(k), w.v.col(j));
    if (owns_k) force.col(k) += f_k;
    if (owns_j) force.col(j) -= f_k;
  }
  return tension_times_length;
}

}  // namespace

double add_bond_forces(const WallParticles& w, const WallMesh& mesh, const BondLaw& law, double ramp, int threads,
                       Eigen::Matrix3Xd& force, BondScratch& scratch) {
  const auto n_bonds = static_cast<Eigen::Index>(mesh.bonds.size());
  scratch.tension_over_length.resize(n_bonds);
  double* t_over_l = scratch.tension_over_length.data();
  for_blocks(threads, n_bonds, [&](Eigen::Index begin, Eigen::Index end) {
    tension_over_length(w, mesh, law, ramp, begin, end, t_over_l);
  });
  auto& parts = scratch.tension_times_length;  // per thread, added in order
  parts.assign(static_cast<std::size_t>(threads), 0.0);
  const auto& spans = scratch.spans.for_threads(threads, static_cast<int>(w.size()), n_bonds, [&](Eigen::Index b) {
    return mesh.bonds[static_cast<std::size_t>(b)];
  });
  for_owned_spans(threads, spans, [&](int t, const OwnedSpan& span) {
    parts[static_cast<std::size_t>(t)] = with_all_or_some(
        span, [&](auto all) { return apply_bonds(all, w, mesh, law.damping_N_s_m, t_over_l, span, force); });
  });
  double tension_times_length = 0;
  for (double part : parts) tension_times_length += part;
  return tension_times_length;
}

}  // namespace cellsim
