#pragma once
// The middle-lamella bond law (model.md §10): a bilinear cohesive law between two facing wall
// particles, opening delta = r - l0. Elastic, F = k delta, up to the peak force F_max at
// delta_0 = F_max / k; then softening linearly to zero at delta_f = 2 G_f a_w / F_max, so a bond that
// separates has taken the fracture energy G_f of the wall area a_w it owns, and lets go gradually
// instead of releasing its stretched spring at once. Damage is kept: a bond opened to delta_peak past
// delta_0 pulls back along the secant F(delta_peak) delta / delta_peak. Closing (delta < 0) is elastic.
// delta_f <= delta_0 (G_f = 0) is the brittle bond: it breaks when its tension exceeds F_max.
#include <algorithm>

#include "core/params.hpp"

namespace cellsim {

struct LamellaLaw {
  double stiffness_N_m = 0;    // k
  double peak_force_N = 0;     // F_max = strength x a_w
  double break_opening_m = 0;  // delta_f

  double elastic_limit_m() const { return peak_force_N / stiffness_N_m; }  // delta_0

  // Whether a bond that has opened as far as peak_opening_m is separated for good.
  bool separated(double peak_opening_m) const {
    return peak_opening_m > elastic_limit_m() && peak_opening_m >= break_opening_m;
  }

  // The tension (positive pulls the two particles together) at opening_m, for a bond whose largest
  // opening so far is peak_opening_m (opening_m <= peak_opening_m).
  double tension_N(double opening_m, double peak_opening_m) const {
    const double elastic_limit = elastic_limit_m();
    if (opening_m <= 0 || peak_opening_m <= elastic_limit) return stiffness_N_m * opening_m;
    if (separated(peak_opening_m)) return 0.0;
    const double envelope = peak_force_N * (break_opening_m - peak_opening_m) / (break_opening_m - elastic_limit);
    return envelope * opening_m / peak_opening_m;
  }

  // The energy the bond stores: the work its tension gives back on closing to l0. Each branch is linear
  // through the origin (elastic, closing, or the secant of a damaged bond), so it is F delta / 2.
  double stored_energy_J(double opening_m, double peak_opening_m) const {
    return separated(peak_opening_m) ? 0.0 : 0.5 * tension_N(opening_m, peak_opening_m) * opening_m;
  }

  // The energy the bond has taken for good, a function of its largest opening only: the envelope's work
  // up to it less what the secant gives back; F_max delta_f / 2 = G_f a_w once separated. A brittle bond
  // lets go of its whole spring, k peak^2 / 2, at the opening where it broke.
  double dissipated_energy_J(double peak_opening_m) const {
    const double elastic_limit = elastic_limit_m();
    if (peak_opening_m <= elastic_limit) return 0.0;
    if (break_opening_m <= elastic_limit) return 0.5 * stiffness_N_m * peak_opening_m * peak_opening_m;
    const double peak = std::min(peak_opening_m, break_opening_m);
    const double envelope = peak_force_N * (break_opening_m - peak) / (break_opening_m - elastic_limit);
    const double work_to_peak = 0.5 * peak_force_N * elastic_limit + 0.5 * (peak - elastic_limit) * (peak_force_N + envelope);
    return work_to_peak - 0.5 * envelope * peak;
  }
};

// delta_f for a fracture energy G_f [J/m^2] over the wall area a_w [m^2] a bond owns (above).
inline double lamella_break_opening_m(double fracture_energy_J_m2, double wall_particle_area_m2, double peak_force_N) {
  return peak_force_N > 0 ? 2.0 * fracture_energy_J_m2 * wall_particle_area_m2 / peak_force_N : 0.0;
}

// The law of the case (tissue.lamella_*), for wall particles that own wall_particle_area_m2 each. Throws
// InputError for a fracture energy too small to reach past the elastic limit (G_f < F_max delta_0 / (2 a_w):
// it would soften over a negative distance).
LamellaLaw make_lamella_law(const Params& p, double wall_particle_area_m2);

}  // namespace cellsim
