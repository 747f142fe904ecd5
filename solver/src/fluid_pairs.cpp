#include "fluid_pairs.hpp"

#include <cmath>
#include <vector>

#include "sph_terms.hpp"

namespace cellsim {

// The per-pair physics is in sph_terms.hpp; this loop inlines it on flat arrays (it is ~half of
// the step's time), visiting each pair of the half list once and applying it to both particles.
void fluid_pair_terms(const FluidParticles& f, const PairList& pairs, const CubicSplineKernel& kernel,
                      const EquationOfState& eos, double viscosity_Pa_s, FluidRates& out) {
  const Eigen::Index n = f.size();
  out.force.setZero(3, n);
  out.drho_dt.setZero(n);
  out.pressure.resize(n);
  std::vector<double> P_over_rho2(static_cast<std::size_t>(n)), inv_rho(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    out.pressure[i] = eos.pressure(f.rho[i]);
    inv_rho[static_cast<std::size_t>(i)] = 1.0 / f.rho[i];
    P_over_rho2[static_cast<std::size_t>(i)] = out.pressure[i] * inv_rho[static_cast<std::size_t>(i)] *
                                               inv_rho[static_cast<std::size_t>(i)];
  }
  const double mu_sum = 2.0 * viscosity_Pa_s;  // mu_i + mu_j: one viscosity for the whole fluid
  const double support2 = kernel.support() * kernel.support();
  const double* x = f.x.data();
  const double* v = f.v.data();
  const double* m = f.m.data();
  double* force = out.force.data();
  double* drho = out.drho_dt.data();
  const int* offset = pairs.offset.data();
  const int* index = pairs.index.data();
  for (int i = 0; i < pairs.rows(); ++i) {
    const double xi0 = x[3 * i], xi1 = x[3 * i + 1], xi2 = x[3 * i + 2];
    const double vi0 = v[3 * i], vi1 = v[3 * i + 1], vi2 = v[3 * i + 2];
    const double mi = m[i], Pi = P_over_rho2[static_cast<std::size_t>(i)], inv_rhoi = inv_rho[static_cast<std::size_t>(i)];
    double fi0 = 0, fi1 = 0, fi2 = 0, drho_i = 0;
    for (int q = offset[i]; q < offset[i + 1]; ++q) {
      const int j = index[q];
      const double d0 = xi0 - x[3 * j], d1 = xi1 - x[3 * j + 1], d2 = xi2 - x[3 * j + 2];
      const double r2 = d0 * d0 + d1 * d1 + d2 * d2;
      if (r2 >= support2) continue;
      const double g = kernel.dW_dr_over_r(std::sqrt(r2));  // grad_i W_ij = g x_ij
      const double u0 = vi0 - v[3 * j], u1 = vi1 - v[3 * j + 1], u2 = vi2 - v[3 * j + 2];
      const double mj = m[j];
      const double v_dot_grad = g * (u0 * d0 + u1 * d1 + u2 * d2);  // v_ij . grad_i W_ij
      drho_i += mj * v_dot_grad;                                     // Eq 10, for i
      drho[j] += mi * v_dot_grad;                                    // Eq 10, for j (same product)
      // Eq 3: -m_i m_j (P_i/rho_i^2 + P_j/rho_j^2) g x_ij; Eq 4: m_i m_j mu_sum/(rho_i rho_j) g v_ij.
      const double mm_g = mi * mj * g;
      const double a = -mm_g * (Pi + P_over_rho2[static_cast<std::size_t>(j)]);
      const double b = mm_g * mu_sum * inv_rhoi * inv_rho[static_cast<std::size_t>(j)];
      const double f0 = a * d0 + b * u0, f1 = a * d1 + b * u1, f2 = a * d2 + b * u2;
      fi0 += f0, fi1 += f1, fi2 += f2;
      force[3 * j] -= f0, force[3 * j + 1] -= f1, force[3 * j + 2] -= f2;
    }
    force[3 * i] += fi0, force[3 * i + 1] += fi1, force[3 * i + 2] += fi2;
    drho[i] += drho_i;
  }
}

}  // namespace cellsim
