#pragma once
// The elastic-plastic wall (docs/model.md §3b; ours, off unless wall.yield_stress_MPa is given): each bond
// is its springs (Eqs 15 and 21) in series with a plastic slider. The slider lengthens by delta_p when the
// bond's tension reaches the wall's flow stress sigma_y + H eps_p (eps_p = delta_p / l0) over the wall
// section the bond carries; the springs see l - delta_p. Rate-independent, tension only (a wall in
// compression folds), linear isotropic hardening: the bilinear elastic-plastic wall of Qiong, Pitt &
// Bartsch (1989). The slider takes T d(delta_p) >= 0 out of the springs: the dissipated energy.
#include <algorithm>
#include <cmath>

#include "physics/wall_terms.hpp"

namespace cellsim::wall {

struct PlasticLaw {
  double yield_stress_Pa = 0;  // sigma_y; 0: elastic (no yield)
  double hardening_Pa = 0;     // H: d(flow stress) / d(plastic strain)
  bool active() const { return yield_stress_Pa > 0; }
};

// One bond's springs against their elastic length l_e = l - delta_p: Eq 15 about l0, Eq 21 about L_ref.
struct BondSprings {
  double G_t_N_m;   // G t0 of the bond
  double k_wc_N_m;  // Eq 21
  double l0_m;      // the fabricated rest length
  double l_ref_m;   // Eq 21's L_ref = l0 [1 - c (1 - X) ramp]
  double tension(double l_e) const {
    return stiff_tension(G_t_N_m, 1.0, l0_m, l_e) + contraction_tension(k_wc_N_m, l_e, l_ref_m);
  }
  double energy(double l_e) const {
    return stiff_energy(G_t_N_m, 1.0, l0_m, l_e) + contraction_energy(k_wc_N_m, l_e, l_ref_m);
  }
  double stiffness(double l_e) const {  // d(tension)/d(l_e)
    return stiff_stiffness(G_t_N_m, l_e / l0_m) + k_wc_N_m;
  }
};

// The tension at which a bond flows after the plastic elongation delta_p: the flow stress times the wall
// section a bond of a triangular network carries, t0 l0 / sqrt 3 (its membrane tension is sqrt 3 T / l).
inline double flow_tension(const PlasticLaw& law, double thickness_m, double l0, double delta_p) {
  return (law.yield_stress_Pa + law.hardening_Pa * delta_p / l0) * thickness_m * l0 / std::sqrt(3.0);
}

// The return map at fixed length l: the plastic elongation after this step (delta_p itself while the bond
// is elastic). The tension falls and the flow tension rises with delta_p, so the root is one; Newton
// finds it in a few steps. A bond within round-off of its flow tension is on it already: mapping the same
// positions again (a continued run's first forces) changes nothing.
inline double return_map(const PlasticLaw& law, const BondSprings& springs, double thickness_m, double delta_p,
                         double l) {
  if (!law.active()) return delta_p;
  const auto excess = [&](double d) { return springs.tension(l - d) - flow_tension(law, thickness_m, springs.l0_m, d); };
  if (excess(delta_p) <= 1e-12 * flow_tension(law, thickness_m, springs.l0_m, delta_p)) return delta_p;
  const double hardening_slope = law.hardening_Pa * thickness_m / std::sqrt(3.0);  // d(flow tension)/d(delta_p)
  double d = delta_p;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double step = excess(d) / (springs.stiffness(l - d) + hardening_slope);
    d += step;
    if (std::abs(step) <= 1e-15 * springs.l0_m) break;
  }
  return std::max(d, delta_p);  // plastic flow only lengthens
}

}  // namespace cellsim::wall
