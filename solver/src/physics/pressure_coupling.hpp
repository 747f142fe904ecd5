#pragma once
// The pressure coupling (coupling.model = pressure; docs/model.md §4, docs/model-closures.md): the wall
// is the boundary of the fluid's SPH sums. A fluid particle i near the wall misses the part of its
// kernel beyond it, so the pressure sum of Eq 3 pushes it outward by V_i ∮ (P_i + P_w) W n dS (the
// divergence theorem on the cut kernel). With the wall's pressure mirrored, P_w = P_i, each wall
// particle k returns that push from the surface it owns (S_k: a third of each adjacent triangle's
// outward area vector), and the continuity equation (Eq 10) gets the wall's matching term:
//   F_ik = -2 V_i P_i w_ik W(r_ik) S_k on fluid i, and -F_ik on wall particle k;
//   d(rho_i)/dt += 2 rho_i w_ik W(r_ik) S_k . (v_i - v_k).
// The 2 is 1/gamma: at a flat wall half the kernel is missing, so sum_i V_i W_ik = 1/2, the wall
// carries P S_k, and the fluid's SPH volume follows the volume the wall sweeps. The force and the
// density term are conjugate: the pair's power, -2 V_i P_i w W S_k . v_ik, is exactly what its density
// term adds to the internal energy (m P / rho^2 d(rho)), so the pair neither makes nor destroys energy.
// w_ik is one-sided: a wall element seen from outside its tangent plane fades out over kFadeOverH h, so
// at an inward fold the far sheet of wall neither pushes fluid through the near one nor squeezes it.
// A short-range backstop keeps a particle from crossing the wall: closer than d_b to an element's
// tangent plane it is pushed back along the element's normal by a pressure p_b(d) = K (1 - d/d_b)^2 in
// place of P_i. The backstop is not conjugate to any density term: its power is a flow of the energy
// account, and its share of the plate's load is recorded (it should stay small).
#include <Eigen/Core>

#include "core/state.hpp"
#include "geometry/neighbours.hpp"
#include "parallel/block_sums.hpp"
#include "physics/kernel.hpp"

namespace cellsim {

// A wall element seen from outside fades out of the coupling over this depth, in units of h.
constexpr double kFadeOverH = 0.1;

struct PressureCouplingLaw {
  double backstop_range_m = 0;     // d_b (0: no backstop)
  double backstop_pressure_Pa = 0; // p_b at the tangent plane (K of Eq 7)
};

// The one-sided weight w(d) of a pair whose fluid particle lies at depth d inside the wall element's
// tangent plane (d < 0: outside): 1 inside, falling as a smoothstep to 0 at d = -fade. For one pair
// (double) or four (simd::double4): t clamped to [0, 1] gives w = 1 and 0 exactly at the ends. A
// multiplication by 1/fade, which a loop computes once: a division a pair would cost as much as W.
template <class T>
T one_sided_weight(T depth, double fade) {
  const T t = simd::min(simd::max(-depth * (1.0 / fade), 0.0), 1.0);
  return 1.0 - t * t * (3.0 - 2.0 * t);
}

// The backstop's pressure at depth d: K (1 - d/d_b)^2 for -d_b < d < d_b, else 0 (a particle farther
// outside than d_b sees another sheet, or has left: the containment check stops the run). Lanes as above.
template <class T>
T backstop_pressure_Pa(T depth, const PressureCouplingLaw& law) {
  if (!(law.backstop_range_m > 0)) return T{} + 0.0;
  const T u = 1.0 - depth * (1.0 / law.backstop_range_m);
  return simd::select(simd::abs(depth) < law.backstop_range_m, law.backstop_pressure_Pa * u * u, T{} + 0.0);
}

// Kept by the caller between steps (no reallocation). Per listed pair q: weight = w W and backstop =
// p_b W at the positions of the last pressure_coupling_weights; per wall particle, S_k.
struct PressureCouplingScratch {
  Eigen::VectorXd weight, backstop;
  Eigen::Matrix3Xd area_vector;  // S_k = N_k / 6 (N_k: the sum of the adjacent triangles' area normals)
  Eigen::Matrix3Xd unit_normal;  // N_k / |N_k|
  bool any_backstop = false;     // some pair has backstop != 0
  BlockSums<Eigen::Matrix3Xd> force_sums, backstop_sums;
  std::vector<double> block_backstop_W;
};

// The pairs' weights at the current positions. vertex_normal: N_k (surface.hpp; |N_k| = twice the area).
void pressure_coupling_weights(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x,
                               const Eigen::Matrix3Xd& vertex_normal, const PairList& pairs,
                               const CubicSplineKernel& kernel, const PressureCouplingLaw& law, int threads,
                               PressureCouplingScratch& scratch);

// Adds the wall term of the continuity equation to drho_dt, with the weights of the last call above.
void add_pressure_coupling_density_rates(const FluidParticles& fluid, const WallParticles& wall, const PairList& pairs,
                                         const PressureCouplingScratch& scratch, int threads, Eigen::VectorXd& drho_dt);

// Adds the forces on the fluid to fluid_force; writes those on the wall to on_wall and the backstop's
// part of them to backstop_on_wall (both overwritten). Returns the backstop's power (W) on fluid and
// wall together. pressure: P_i (Eq 7), with the weights of the last pressure_coupling_weights.
double pressure_coupling_forces(const FluidParticles& fluid, const Eigen::VectorXd& pressure, const WallParticles& wall,
                                const PairList& pairs, int threads, PressureCouplingScratch& scratch,
                                Eigen::Matrix3Xd& fluid_force, Eigen::Matrix3Xd& on_wall,
                                Eigen::Matrix3Xd& backstop_on_wall);

}  // namespace cellsim
