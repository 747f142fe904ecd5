#pragma once
// A closed cell of one uniform pressure (model.md §11, fluid.model = cavity): its fluid of mass M fills
// the volume V its wall encloses, at density M / V and Eq 7's pressure. The pressure pushes on wall
// particle k with P dV/dx_k, the exact gradient of the fluid's stored energy M e(M/V) at fixed M
// (de = P / rho^2 drho: d(M e)/dV = -P), so the energy account closes.
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "geometry/block_stiffness.hpp"
#include "geometry/wall_mesh.hpp"
#include "physics/eos.hpp"

namespace cellsim {

// dV/dx_k of the signed-tetrahedra volume: a sixth of the sum of the area normals (v - u) x (w - u) of
// the triangles at k, which is WallSurface::vertex_normal / 6 (exact for a closed surface).
inline Eigen::Vector3d volume_gradient(const Eigen::Vector3d& vertex_normal) { return vertex_normal / 6.0; }

// dV/dx of each cell's enclosed volume on its wall particles, stacked (x, y, z per particle) [m^2].
inline Eigen::VectorXd stacked_volume_gradients(const Eigen::Matrix3Xd& vertex_normal) {
  Eigen::VectorXd g(vertex_normal.size());
  for (Eigen::Index k = 0; k < vertex_normal.cols(); ++k) g.segment<3>(3 * k) = volume_gradient(vertex_normal.col(k));
  return g;
}

// Eq 11 over an increment dt, backward Euler, for one closed cell (the cell as one particle, n_f = 1):
// the density rho at which M_n + dt dM/dt(rho) fills V, with dM/dt = -A L_p rho (P(rho) - P_T), i.e.
//   rho V = M_n - a rho (P(rho) - P_T),  a = dt A L_p.
// a = 0: the mass is kept (rho = M_n / V); a = infinity: drained, P = P_T (rho = rho0). The left side
// minus the right grows with rho wherever it is positive, so the root is unique: safeguarded Newton
// from M_n / V within [0, max(M_n / V, rho0)], where the sign changes.
inline double implicit_cavity_density(double mass_kg, double volume_m3, double a_m3_Pa, const EquationOfState& eos) {
  if (a_m3_Pa == 0) return mass_kg / volume_m3;
  if (std::isinf(a_m3_Pa)) return eos.rho0_kg_m3;
  double lo = 0, hi = std::max(mass_kg / volume_m3, eos.rho0_kg_m3);
  double rho = mass_kg / volume_m3;
  const double K = eos.bulk_modulus_Pa, gamma = eos.exponent;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double excess = eos.pressure(rho) - eos.turgor_Pa;
    const double g = rho * volume_m3 - mass_kg + a_m3_Pa * rho * excess;
    if (g == 0) return rho;
    (g < 0 ? lo : hi) = rho;
    const double slope = volume_m3 + a_m3_Pa * (excess + gamma * K * std::pow(rho / eos.rho0_kg_m3, gamma));
    double next = rho - g / slope;
    if (!(slope > 0) || !(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket
    if (std::abs(next - rho) <= 1e-15 * rho) return next;
    rho = next;
  }
  return rho;
}

// The cell's fluid as a spring of the enclosed volume: d P / d V at fixed M is -rho P'(rho) / V, with
// P'(rho) = gamma K rho^(gamma-1) / rho0^gamma (Eq 7).
inline double cavity_volume_stiffness_Pa_m3(double rho, double volume_m3, const EquationOfState& eos) {
  return eos.exponent * eos.bulk_modulus_Pa * std::pow(rho / eos.rho0_kg_m3, eos.exponent) / volume_m3;
}

// The same within an increment (implicit_cavity_density): differentiating rho V = M_n - a rho (P - P_T) at
// fixed M_n, -dP/dV = rho P' / (V + a (P - P_T + rho P')), with rho P' = V k0 (k0 the sealed value above).
// a = 0 gives k0; a drained cell (a = infinity) holds P = P_T whatever its volume: 0.
inline double increment_volume_stiffness_Pa_m3(double rho, double volume_m3, double a_m3_Pa, const EquationOfState& eos) {
  if (std::isinf(a_m3_Pa)) return 0;
  const double rho_dP = volume_m3 * cavity_volume_stiffness_Pa_m3(rho, volume_m3, eos);
  return rho_dP / (volume_m3 + a_m3_Pa * (eos.pressure(rho) - eos.turgor_Pa + rho_dP));
}

// The pressures' share of the wall's stiffness, added into K, for closed cells of uniform pressure P: -P
// d2V/dx2 of each cell's enclosed volume at fixed P, the follower stiffness of a pressure that turns with
// the wall. Symmetric, indefinite; a cell's blocks join only the corners of its triangles (the bonds' pattern).
void add_pressure_follower_stiffness(const Eigen::Matrix3Xd& x, const WallMesh& mesh,
                                     const std::vector<double>& cell_pressure_Pa, BlockStiffness& K);

}  // namespace cellsim
