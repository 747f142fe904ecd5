#pragma once
// The pressure coupling (coupling.model = pressure; model.md §4, docs/model-closures.md): the wall
// is the boundary of the fluid's SPH sums. A fluid particle i near the wall misses the part of its
// kernel beyond it, so the pressure sum of Eq 3 pushes it outward by V_i ∮ (P_i + P_w) W n dS (the
// divergence theorem on the cut kernel, with P_w the pressure beyond). The wall returns exactly
// that, from the surface each wall particle k owns (the outward area vector S_k, a third of each
// adjacent triangle's):
//   F_ik = -V_i (P_i + P_k) W(r_ik) S_k on fluid i, and -F_ik on wall particle k,
// with P_k the fluid pressure at wall particle k, the Shepard average of its fluid neighbours' (as
// Adami, Hu & Adams 2012 extrapolate it to their wall). A uniformly pressurised fluid is then at
// rest next to the wall, and the wall carries P x its area. P_i + P_k is taken as at least 0: a
// fluid in tension is not pulled through the wall.
#include <Eigen/Core>

#include "core/state.hpp"
#include "geometry/neighbours.hpp"
#include "parallel/block_sums.hpp"
#include "physics/kernel.hpp"

namespace cellsim {

// The coefficient V_i max(P_i + P_k, 0) W(r) of S_k for one pair.
inline double pressure_coupling_coefficient(double volume_i, double pressure_i, double pressure_k, double W) {
  const double sum = pressure_i + pressure_k;
  return volume_i * (sum > 0 ? sum : 0.0) * W;
}

// Scratch kept by the caller between steps (no reallocation): W of every listed pair; per wall
// particle the Shepard weight (row 0) and P_k (row 1); per-thread sums (block_sums.hpp).
struct PressureCouplingScratch {
  Eigen::VectorXd pair_W;
  Eigen::Matrix2Xd shepard;
  BlockSums<Eigen::Matrix2Xd> shepard_sums;
  BlockSums<Eigen::Matrix3Xd> force_sums;
};

// Adds the forces on the fluid to fluid_force and the wall term of Eq 10 to drho_dt, and writes the
// forces on the wall to on_wall (overwritten). pressure: P_i (Eq 7); vertex_normal: the sum of each
// wall particle's adjacent triangles' area normals (surface.hpp; |N| = twice the area), so S_k = N_k / 6.
void pressure_coupling_forces(const FluidParticles& fluid, const Eigen::VectorXd& pressure, const WallParticles& wall,
                              const Eigen::Matrix3Xd& vertex_normal, const PairList& pairs,
                              const CubicSplineKernel& kernel, int threads, PressureCouplingScratch& scratch,
                              Eigen::Matrix3Xd& fluid_force, Eigen::VectorXd& drho_dt, Eigen::Matrix3Xd& on_wall);

}  // namespace cellsim
