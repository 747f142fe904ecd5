#include "fluid_pairs.hpp"

#include <cmath>

#include "sph_terms.hpp"

namespace cellsim {
namespace {
using Vec3 = Eigen::Map<const Eigen::Vector3d>;
}  // namespace

// Each pair of the half list is visited once and applied to both particles, with the per-pair
// physics of sph_terms.hpp (Eqs 3, 4, 10). Per-particle factors (P/rho^2, m/rho) are computed
// once before the loop; the loop reads the flat column-major arrays directly.
void fluid_pair_terms(const FluidParticles& f, const PairList& pairs, const CubicSplineKernel& kernel,
                      const EquationOfState& eos, double viscosity_Pa_s, FluidRates& out) {
  const Eigen::Index n = f.size();
  out.force.setZero(3, n);
  out.drho_dt.setZero(n);
  out.pressure.resize(n);
  out.P_over_rho2.resize(n);
  out.volume.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    out.pressure[i] = eos.pressure(f.rho[i]);
    out.P_over_rho2[i] = out.pressure[i] / (f.rho[i] * f.rho[i]);
    out.volume[i] = f.m[i] / f.rho[i];
  }
  const double mu_sum = 2.0 * viscosity_Pa_s;  // mu_i + mu_j: one viscosity for the whole fluid
  const double* x = f.x.data();
  const double* v = f.v.data();
  const double* m = f.m.data();
  double* force = out.force.data();
  double* drho = out.drho_dt.data();
  const double support2 = kernel.support() * kernel.support();
  const int* offset = pairs.offset.data();
  const int* index = pairs.index.data();
  // Pass 1: the listed pairs within the kernel support (the list has a skin), compacted without
  // branches, and their kernel gradients g = (1/r) dW/dr in one vectorised stream.
  out.active_offset.resize(pairs.offset.size());
  out.active_index.resize(pairs.index.size());
  out.pair_g.resize(static_cast<Eigen::Index>(pairs.index.size()));
  int* active_offset = out.active_offset.data();
  int* active_index = out.active_index.data();
  double* g = out.pair_g.data();
  int n_active = 0;
  active_offset[0] = 0;
  for (int i = 0; i < pairs.rows(); ++i) {
    const Eigen::Vector3d xi = Vec3(x + 3 * i);
    for (int q = offset[i]; q < offset[i + 1]; ++q) {
      const int j = index[q];
      const double r2 = (xi - Vec3(x + 3 * j)).squaredNorm();
      active_index[n_active] = j;
      g[n_active] = r2;
      n_active += r2 < support2;
    }
    active_offset[i + 1] = n_active;
  }
  kernel.dW_dr_over_r_from_r2(g, g, static_cast<std::size_t>(n_active));
  // Pass 2: the pair terms.
  for (int i = 0; i < pairs.rows(); ++i) {
    const Eigen::Vector3d xi = Vec3(x + 3 * i), vi = Vec3(v + 3 * i);
    const double mi = m[i], Ai = out.P_over_rho2[i], Vi = out.volume[i];
    Eigen::Vector3d force_i = Eigen::Vector3d::Zero();
    double drho_i = 0;
    for (int q = active_offset[i]; q < active_offset[i + 1]; ++q) {
      const int j = active_index[q];
      const Eigen::Vector3d xij = xi - Vec3(x + 3 * j);
      const Eigen::Vector3d vij = vi - Vec3(v + 3 * j);
      const double v_dot_grad = g[q] * vij.dot(xij);  // v_ij . grad_i W_ij, the same for j's view
      drho_i += sph::continuity_rate(v_dot_grad, m[j]);
      drho[j] += sph::continuity_rate(v_dot_grad, mi);
      const Eigen::Vector3d fij = g[q] * (sph::pressure_coefficient(mi, m[j], Ai, out.P_over_rho2[j]) * xij +
                                          sph::viscous_coefficient(mu_sum, Vi, out.volume[j]) * vij);
      force_i += fij;
      Eigen::Map<Eigen::Vector3d>(force + 3 * j) -= fij;
    }
    Eigen::Map<Eigen::Vector3d>(force + 3 * i) += force_i;
    drho[i] += drho_i;
  }
}

}  // namespace cellsim
