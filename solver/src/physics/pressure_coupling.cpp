#include "physics/pressure_coupling.hpp"

namespace cellsim {
namespace {

// Pass 1 over fluid rows [begin, end): W of every pair, and the Shepard sums of P_k (row 0: the
// weight sum V_i W, row 1: V_i W P_i).
void add_shepard_sums(const FluidParticles& fluid, const Eigen::VectorXd& pressure, const WallParticles& wall,
                      const PairList& pairs, const CubicSplineKernel& kernel, Eigen::Index begin, Eigen::Index end,
                      double* W, Eigen::Matrix2Xd& shepard) {
  const int* offset = pairs.offset.data();
  const int* index = pairs.index.data();
  for (Eigen::Index i = begin; i < end; ++i) {
    const Eigen::Vector3d xi = fluid.x.col(i);
    const double volume_i = fluid.m[i] / fluid.rho[i];
    for (int q = offset[i]; q < offset[i + 1]; ++q) {
      const int k = index[q];
      W[q] = kernel.W((xi - wall.x.col(k)).norm());
      shepard(0, k) += volume_i * W[q];
      shepard(1, k) += volume_i * W[q] * pressure[i];
    }
  }
}

// Pass 2 over fluid rows [begin, end): the pair forces, and the wall term of the continuity
// equation, rho_i sum_k W_ik (v_i - v_k) . S_k.
void add_pair_forces(const FluidParticles& fluid, const Eigen::VectorXd& pressure, const WallParticles& wall,
                     const Eigen::Matrix3Xd& vertex_normal, const PairList& pairs, const double* W,
                     const Eigen::Matrix2Xd& shepard, Eigen::Index begin, Eigen::Index end,
                     Eigen::Matrix3Xd& fluid_force, Eigen::VectorXd& drho_dt, Eigen::Matrix3Xd& on_wall) {
  const int* offset = pairs.offset.data();
  const int* index = pairs.index.data();
  for (Eigen::Index i = begin; i < end; ++i) {
    const double volume_i = fluid.m[i] / fluid.rho[i];
    Eigen::Vector3d force_i = Eigen::Vector3d::Zero();
    double divergence = 0;
    for (int q = offset[i]; q < offset[i + 1]; ++q) {
      const int k = index[q];
      const Eigen::Vector3d S_k = vertex_normal.col(k) / 6.0;
      const Eigen::Vector3d fik = -pressure_coupling_coefficient(volume_i, pressure[i], shepard(1, k), W[q]) * S_k;
      force_i += fik;
      on_wall.col(k) -= fik;
      divergence += W[q] * (fluid.v.col(i) - wall.v.col(k)).dot(S_k);
    }
    fluid_force.col(i) += force_i;
    drho_dt[i] += fluid.rho[i] * divergence;
  }
}

}  // namespace

// What the passes add to wall particles goes through per-thread sums (block_sums.hpp).
void pressure_coupling_forces(const FluidParticles& fluid, const Eigen::VectorXd& pressure, const WallParticles& wall,
                              const Eigen::Matrix3Xd& vertex_normal, const PairList& pairs,
                              const CubicSplineKernel& kernel, int threads, PressureCouplingScratch& scratch,
                              Eigen::Matrix3Xd& fluid_force, Eigen::VectorXd& drho_dt, Eigen::Matrix3Xd& on_wall) {
  scratch.pair_W.resize(static_cast<Eigen::Index>(pairs.index.size()));
  double* W = scratch.pair_W.data();
  auto& shepard = scratch.shepard;
  shepard.setZero(2, wall.size());
  scratch.shepard_sums.add(threads, pairs.rows(), shepard,
                           [&](int, Eigen::Index begin, Eigen::Index end, Eigen::Matrix2Xd& out) {
                             add_shepard_sums(fluid, pressure, wall, pairs, kernel, begin, end, W, out);
                           });
  for (Eigen::Index k = 0; k < wall.size(); ++k)
    if (shepard(0, k) > 0) shepard(1, k) /= shepard(0, k);
  on_wall.setZero(3, wall.size());
  scratch.force_sums.add(threads, pairs.rows(), on_wall, [&](int, Eigen::Index begin, Eigen::Index end,
                                                             Eigen::Matrix3Xd& out) {
    add_pair_forces(fluid, pressure, wall, vertex_normal, pairs, W, shepard, begin, end, fluid_force, drho_dt, out);
  });
}

}  // namespace cellsim
