#pragma once
// Per-pair SPH terms of Table 1, for fluid particles i and j at distance r, x_ij = x_i - x_j.
// F_ij is the force on i; j gets -F_ij (each term is antisymmetric: Newton's third law).
// Both forces are a scalar times grad_i W_ij = g x_ij (g = (1/r) dW/dr), or times g v_ij, so the
// pair loop computes the two scalar coefficients and adds coefficient x vector once. The
// coefficient functions take one pair (double) or four (simd::double4, the pair loop's lanes).
namespace cellsim::sph {

// Pressure force, Eq 3 (symmetric form): F_ij = -m_i m_j (P_i/rho_i^2 + P_j/rho_j^2) grad_i W_ij;
// this returns the factor of g x_ij.
template <class T>
T pressure_coefficient(T mi, T mj, T Pi_over_rho2, T Pj_over_rho2) {
  return -mi * mj * (Pi_over_rho2 + Pj_over_rho2);
}

// Viscous force, Eq 4 in Morris' dissipative form (model.md §2: the printed minus adds energy):
// F_ij = m_i m_j (mu_i + mu_j)/(rho_i rho_j) (1/r dW/dr) v_ij, written with the particle volumes
// V = m/rho (computed once per particle, not per pair); this returns the factor of g v_ij.
template <class T>
T viscous_coefficient(T mu_sum, T Vi, T Vj) {
  return mu_sum * Vi * Vj;
}

// Density diffusion of delta-SPH (Molteni & Colagrossi 2009; delta = 0.1 in Antuono et al. 2010), our
// option (fluid.density_diffusion): d(rho_i)/dt += delta h c0 sum_j V_j psi_ij . grad_i W_ij with
// psi_ij = 2 (rho_i - rho_j) x_ij / r^2, i.e. 2 g (rho_i - rho_j) V_j per pair (g = (1/r) dW/dr <= 0, so
// a denser particle loses density to its neighbours; j gains what i loses, weighted by V_i). Mass is
// untouched; the acoustic noise of the density field is damped. This returns the part of d(rho_i)/dt.
template <class T>
T density_diffusion_rate(T diffusion_m2_s, T g, T rho_i, T rho_j, T V_other) {
  return diffusion_m2_s * 2.0 * g * (rho_i - rho_j) * V_other;
}

// Continuity, Eq 10: the contribution of j to d(rho_i)/dt is m_j v_ij . grad_i W_ij
// (and that of i to d(rho_j)/dt is m_i v_ij . grad_i W_ij: same dot product).
template <class T>
T continuity_rate(T v_dot_grad, T m_other) {
  return m_other * v_dot_grad;
}

}  // namespace cellsim::sph
