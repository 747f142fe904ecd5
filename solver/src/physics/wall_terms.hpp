#pragma once
// Per-bond wall forces of Table 2, as magnitudes along the bond (tension positive: pulls the
// two particles together), and the bond damping, Eq 16.
#include <cmath>

#include <Eigen/Core>

namespace cellsim::wall {

// Stiff force, Eq 15 with the wall thickness (model.md §3): (G t0 l0 / sqrt 3)(lambda - 1/lambda).
inline double stiff_tension(double G_Pa, double thickness_m, double l0, double l) {
  const double lambda = l / l0;
  return G_Pa * thickness_m * l0 / std::sqrt(3.0) * (lambda - 1.0 / lambda);
}

// The stiff spring's stiffness, d(Eq 15's tension)/dl: (G t0 / sqrt 3)(1 + 1 / lambda^2), with G t0 the
// bond's (wall_bonds.hpp); 2 G t0 / sqrt 3 at rest, where the time step's wall limit takes it (step_checks).
inline double stiff_stiffness(double G_t_N_m, double lambda) {
  return G_t_N_m / std::sqrt(3.0) * (1.0 + 1.0 / (lambda * lambda));
}
inline double stiff_stiffness_at_rest(double G_t_N_m) { return stiff_stiffness(G_t_N_m, 1.0); }

// The stiff spring's energy, the integral of Eq 15's tension over l from l0:
// (G t0 l0^2 / sqrt 3) ((lambda^2 - 1) / 2 - ln lambda).
inline double stiff_energy(double G_Pa, double thickness_m, double l0, double l) {
  const double lambda = l / l0;
  return G_Pa * thickness_m * l0 * l0 / std::sqrt(3.0) * (0.5 * (lambda * lambda - 1.0) - std::log(lambda));
}

// Contraction, Eq 21: k_wc (l - L_ref), L_ref = l0 [1 - c (1 - X) ramp], ramp in [0, 1] (drying.hpp).
inline double contraction_tension(double k_wc, double l, double l_ref) { return k_wc * (l - l_ref); }
inline double contraction_energy(double k_wc, double l, double l_ref) { return 0.5 * k_wc * (l - l_ref) * (l - l_ref); }

inline double contraction_rest_length(double l0, double contraction_ratio, double dryness, double ramp) {
  return l0 * (1.0 - contraction_ratio * (1.0 - dryness) * ramp);
}

// Damping, Eq 16: F_k = -gamma (v_k - v_j) on particle k (and the opposite on j); it takes
// gamma |v_k - v_j|^2 of power out of the wall (damping_loss_W).
inline Eigen::Vector3d damping_force(double gamma, const Eigen::Vector3d& vk, const Eigen::Vector3d& vj) {
  return -gamma * (vk - vj);
}
inline double damping_loss_W(double gamma, const Eigen::Vector3d& vk, const Eigen::Vector3d& vj) {
  return gamma * (vk - vj).squaredNorm();
}

}  // namespace cellsim::wall
