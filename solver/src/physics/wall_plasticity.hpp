#pragma once
// The elastic-plastic wall (docs/model.md §3b; ours, off unless wall.yield_stress_MPa is given): a bond
// yields when its tension reaches the wall's flow stress sigma_y + H eps_p over the wall section it
// carries, and then lengthens its rest length l_p (both springs, Eqs 15 and 21, rest on l_p) so that the
// tension stays on the flow stress. Rate-independent, tension only (a wall in compression folds), with
// linear isotropic hardening H (the bilinear elastic-plastic wall of Qiong, Pitt & Bartsch 1989).
#include <cmath>

#include "physics/wall_terms.hpp"

namespace cellsim::wall {

struct PlasticLaw {
  double yield_stress_Pa = 0;  // sigma_y; 0: elastic (no yield)
  double hardening_Pa = 0;     // H: d(flow stress) / d(plastic strain)
  bool active() const { return yield_stress_Pa > 0; }
};

// One bond's springs at a given rest length l_p: Eq 15 (G t0 on l_p) plus Eq 21 (k_wc about l_p's
// contracted length L_ref = l_p [1 - c (1 - X) ramp]).
struct BondSprings {
  double G_t_N_m;        // G t0 of the bond
  double k_wc_N_m;       // Eq 21
  double l_ref_ratio;    // L_ref / l_p = 1 - c (1 - X) ramp
  double tension(double l_p, double l) const {
    return stiff_tension(G_t_N_m, 1.0, l_p, l) + contraction_tension(k_wc_N_m, l, l_p * l_ref_ratio);
  }
  double energy(double l_p, double l) const {
    return stiff_energy(G_t_N_m, 1.0, l_p, l) + contraction_energy(k_wc_N_m, l, l_p * l_ref_ratio);
  }
};

// The tension at which a bond of fabricated length l0 and wall thickness t0 flows, after plastic strain
// eps_p = ln(l_p / l0): the flow stress over the wall section a bond of a triangular network carries,
// t0 l0 / sqrt 3 (its membrane tension tau = sqrt 3 T / l, model.md §3).
inline double flow_tension(const PlasticLaw& law, double thickness_m, double l0, double l_p) {
  return (law.yield_stress_Pa + law.hardening_Pa * std::log(l_p / l0)) * thickness_m * l0 / std::sqrt(3.0);
}

// The return map at fixed length l: the rest length after this step (l_p itself while the bond is
// elastic). The tension falls and the flow tension rises with l_p, so the root is one and Newton finds
// it in a few steps; the energy the bond loses, springs.energy(l_p) - springs.energy(result), is dissipated.
inline double return_map(const PlasticLaw& law, const BondSprings& springs, double thickness_m, double l0, double l_p,
                         double l) {
  const auto excess = [&](double rest) { return springs.tension(rest, l) - flow_tension(law, thickness_m, l0, rest); };
  if (!law.active() || excess(l_p) <= 0) return l_p;
  const double section = thickness_m * l0 / std::sqrt(3.0);
  double rest = l_p;
  for (int iteration = 0; iteration < 50; ++iteration) {
    // d(excess)/d(l_p): Eq 15's -2 G t0 l_p / (sqrt 3 l), Eq 21's -k_wc L_ref/l_p, the hardening's -H section / l_p.
    const double slope = -2.0 * springs.G_t_N_m * rest / (std::sqrt(3.0) * l) - springs.k_wc_N_m * springs.l_ref_ratio -
                         law.hardening_Pa * section / rest;
    const double step = -excess(rest) / slope;
    rest += step;
    if (std::abs(step) <= 1e-15 * rest) break;
  }
  return std::max(rest, l_p);  // plastic flow only lengthens
}

}  // namespace cellsim::wall
