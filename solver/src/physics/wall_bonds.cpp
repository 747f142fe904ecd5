#include "physics/wall_bonds.hpp"

#include <cmath>

#include "parallel/threads.hpp"
#include "physics/wall_terms.hpp"

namespace cellsim {

namespace {

// The per-block loops are functions of their own, with the scalars as value parameters: inside a
// lambda that is also handed to other threads they would be re-read after every store.

// What passes 1 and 2 sum over their bonds.
struct TensionSums {
  double contraction_times_l0 = 0, plastic_loss_J = 0;
  TensionSums operator+(const TensionSums& o) const {
    return {contraction_times_l0 + o.contraction_times_l0, plastic_loss_J + o.plastic_loss_J};
  }
};

// A plastic law's return map for bonds [begin, end) at their lengths sqrt(length2[b]): lengthens their
// sliders delta_p[b] and returns the energy the springs lost to them (wall_plasticity.hpp).
double yield_bonds(const WallMesh& mesh, const BondLaw& law, double ramp, Eigen::Index begin, Eigen::Index end,
                   const double* length2, double* delta_p) {
  double loss = 0;
  for (Eigen::Index b = begin; b < end; ++b) {
    const double l = std::sqrt(length2[b]), l0 = mesh.rest_length_m[b];
    const wall::BondSprings springs{law.G_t_N_m[b], law.contraction_N_m, l0,
                                    wall::contraction_rest_length(l0, law.contraction_ratio, law.dryness, ramp)};
    const double flowed = wall::return_map(law.plastic, springs, law.thickness_m[b], delta_p[b], l);
    if (flowed == delta_p[b]) continue;
    loss += springs.energy(l - delta_p[b]) - springs.energy(l - flowed);
    delta_p[b] = flowed;
  }
  return loss;
}

// Passes 1 and 2 for bonds [begin, end): squared lengths, (the return map of a plastic law,) then
// tension / length over the flat array (vectorised: it holds the square roots and divisions). The
// springs stretch by the bond's length less its slider's elongation delta_p.
TensionSums tension_over_length(const WallParticles& w, const WallMesh& mesh, const BondLaw& law, double ramp,
                                Eigen::Index begin, Eigen::Index end, double* delta_p, double* t_over_l) {
  for (Eigen::Index b = begin; b < end; ++b) {
    const auto& bond = mesh.bonds[static_cast<std::size_t>(b)];
    t_over_l[b] = (w.x.col(bond[1]) - w.x.col(bond[0])).squaredNorm();
  }
  TensionSums sums;
  if (law.plastic.active()) sums.plastic_loss_J = yield_bonds(mesh, law, ramp, begin, end, t_over_l, delta_p);
  const double* rest = mesh.rest_length_m.data();
  const double* G_t = law.G_t_N_m.data();
  for (Eigen::Index b = begin; b < end; ++b) {
    const double l = std::sqrt(t_over_l[b]), l_e = l - delta_p[b];
    const double l_ref = wall::contraction_rest_length(rest[b], law.contraction_ratio, law.dryness, ramp);
    const double contraction = wall::contraction_tension(law.contraction_N_m, l_e, l_ref);
    t_over_l[b] = (wall::stiff_tension(G_t[b], 1.0, rest[b], l_e) + contraction) / l;
    sums.contraction_times_l0 += contraction * rest[b];
  }
  return sums;
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

// The power Eq 16 takes out of bonds [begin, end) (the energy account): a pass of its own, so that the
// force pass above stays as it was (its sums bit for bit).
double bonds_damping_loss_W(const WallParticles& w, const WallMesh& mesh, double damping_N_s_m, Eigen::Index begin,
                            Eigen::Index end) {
  double loss[4] = {0, 0, 0, 0};  // four running sums: one would wait on every addition
  for (Eigen::Index b = begin; b < end; ++b) {
    const auto& bond = mesh.bonds[static_cast<std::size_t>(b)];
    loss[b & 3] += wall::damping_loss_W(damping_N_s_m, w.v.col(bond[0]), w.v.col(bond[1]));
  }
  return (loss[0] + loss[1]) + (loss[2] + loss[3]);
}

}  // namespace

BondLaw make_bond_law(const Params& p, const PropertyFactors& factors) {
  BondLaw law{{}, {}, p.contraction_stiffness_N_m, p.contraction_ratio, p.dryness, p.damping_N_s_m,
              {p.yield_stress_Pa.value_or(0.0), p.hardening_Pa}};
  for (std::size_t b = 0; b < factors.G.size(); ++b) {
    law.thickness_m.push_back(p.thickness_m * factors.thickness[b]);
    law.G_t_N_m.push_back(p.G_Pa * p.thickness_m * factors.G[b] * factors.thickness[b]);
  }
  return law;
}

BondSums add_bond_forces(const WallParticles& w, const WallMesh& mesh, const BondLaw& law, double ramp, int threads,
                         std::vector<double>& plastic_elongation_m, Eigen::Matrix3Xd& force, BondScratch& scratch) {
  const auto n_bonds = static_cast<Eigen::Index>(mesh.bonds.size());
  scratch.tension_over_length.resize(n_bonds);
  double* t_over_l = scratch.tension_over_length.data();
  double* delta_p = plastic_elongation_m.data();
  const TensionSums sums = reduce_blocks<TensionSums>(
      threads, n_bonds,
      [&](Eigen::Index begin, Eigen::Index end) {
        return tension_over_length(w, mesh, law, ramp, begin, end, delta_p, t_over_l);
      },
      [](const TensionSums& a, const TensionSums& b) { return a + b; });
  auto& parts = scratch.tension_times_length;  // per thread, added in order
  parts.assign(static_cast<std::size_t>(threads), 0.0);
  const auto& spans = scratch.spans.for_threads(threads, static_cast<int>(w.size()), n_bonds, [&](Eigen::Index b) {
    return mesh.bonds[static_cast<std::size_t>(b)];
  });
  for_owned_spans(threads, spans, [&](int t, const OwnedSpan& span) {
    parts[static_cast<std::size_t>(t)] = with_all_or_some(
        span, [&](auto all) { return apply_bonds(all, w, mesh, law.damping_N_s_m, t_over_l, span, force); });
  });
  BondSums total;
  total.contraction_times_l0_N_m = sums.contraction_times_l0;
  total.plastic_loss_J = sums.plastic_loss_J;
  for (double part : parts) total.tension_times_length += part;
  total.damping_loss_W = reduce_blocks<double>(
      threads, n_bonds,
      [&](Eigen::Index begin, Eigen::Index end) { return bonds_damping_loss_W(w, mesh, law.damping_N_s_m, begin, end); },
      [](double a, double b) { return a + b; });
  return total;
}

BondEnergy bond_energy(const WallParticles& w, const WallMesh& mesh, const BondLaw& law, double ramp,
                       const std::vector<double>& plastic_elongation_m) {
  BondEnergy e;
  for (std::size_t b = 0; b < mesh.bonds.size(); ++b) {
    const double l = (w.x.col(mesh.bonds[b][1]) - w.x.col(mesh.bonds[b][0])).norm() - plastic_elongation_m[b];
    const double l0 = mesh.rest_length_m[b];
    const double l_ref = wall::contraction_rest_length(l0, law.contraction_ratio, law.dryness, ramp);
    e.stiff_J += wall::stiff_energy(law.G_t_N_m[b], 1.0, l0, l);
    e.contraction_J += wall::contraction_energy(law.contraction_N_m, l, l_ref);
  }
  return e;
}

}  // namespace cellsim
