#include "fluid_pairs.hpp"

#include <cmath>

#include "sph_terms.hpp"

namespace cellsim {

// Each pair of the half list is visited once and applied to both particles, with the per-pair
// physics of sph_terms.hpp (Eqs 3, 4, 10).
void fluid_pair_terms(const FluidParticles& f, const PairList& pairs, const CubicSplineKernel& kernel,
                      const EquationOfState& eos, double viscosity_Pa_s, FluidRates& out) {
  const Eigen::Index n = f.size();
  out.force.setZero(3, n);
  out.drho_dt.setZero(n);
  out.pressure.resize(n);
  Eigen::VectorXd P_over_rho2(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    out.pressure[i] = eos.pressure(f.rho[i]);
    P_over_rho2[i] = out.pressure[i] / (f.rho[i] * f.rho[i]);
  }
  const double mu_sum = 2.0 * viscosity_Pa_s;  // mu_i + mu_j: one viscosity for the whole fluid
  const double support2 = kernel.support() * kernel.support();
  for (int i = 0; i < pairs.rows(); ++i) {
    const Eigen::Vector3d xi = f.x.col(i), vi = f.v.col(i);
    Eigen::Vector3d force_i = Eigen::Vector3d::Zero();
    double drho_i = 0;
    for (int q = pairs.offset[static_cast<std::size_t>(i)]; q < pairs.offset[static_cast<std::size_t>(i) + 1]; ++q) {
      const int j = pairs.index[static_cast<std::size_t>(q)];
      const Eigen::Vector3d xij = xi - f.x.col(j);
      const double r2 = xij.squaredNorm();
      if (r2 >= support2) continue;
      const double g = kernel.dW_dr_over_r(std::sqrt(r2));  // grad_i W_ij = g x_ij
      const Eigen::Vector3d vij = vi - f.v.col(j);
      const double v_dot_grad = g * vij.dot(xij);  // v_ij . grad_i W_ij, the same for j's view
      drho_i += sph::continuity_rate(v_dot_grad, f.m[j]);
      out.drho_dt[j] += sph::continuity_rate(v_dot_grad, f.m[i]);
      const Eigen::Vector3d fij = sph::pressure_force(f.m[i], f.m[j], P_over_rho2[i], P_over_rho2[j], g, xij) +
                                  sph::viscous_force(f.m[i], f.m[j], mu_sum, f.rho[i], f.rho[j], g, vij);
      force_i += fij;
      out.force.col(j) -= fij;
    }
    out.force.col(i) += force_i;
    out.drho_dt[i] += drho_i;
  }
}

}  // namespace cellsim
