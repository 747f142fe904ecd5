#include "pressure_coupling.hpp"

namespace cellsim {

// Pass 1: W of every pair and the Shepard sums of P_k; pass 2: the pair forces and the wall term
// of the continuity equation, rho_i sum_k W_ik (v_i - v_k) . S_k.
void pressure_coupling_forces(const FluidParticles& fluid, const Eigen::VectorXd& pressure, const WallParticles& wall,
                              const Eigen::Matrix3Xd& vertex_normal, const PairList& pairs,
                              const CubicSplineKernel& kernel, PressureCouplingScratch& scratch,
                              Eigen::Matrix3Xd& fluid_force, Eigen::VectorXd& drho_dt, Eigen::Matrix3Xd& on_wall) {
  auto& W = scratch.pair_W;
  auto& P_k = scratch.wall_pressure;
  W.resize(static_cast<Eigen::Index>(pairs.index.size()));
  scratch.weight.setZero(wall.size());
  P_k.setZero(wall.size());
  for (int i = 0; i < pairs.rows(); ++i) {
    const Eigen::Vector3d xi = fluid.x.col(i);
    const double volume_i = fluid.m[i] / fluid.rho[i];
    for (int q = pairs.offset[static_cast<std::size_t>(i)]; q < pairs.offset[static_cast<std::size_t>(i) + 1]; ++q) {
      const int k = pairs.index[static_cast<std::size_t>(q)];
      W[q] = kernel.W((xi - wall.x.col(k)).norm());
      scratch.weight[k] += volume_i * W[q];
      P_k[k] += volume_i * W[q] * pressure[i];
    }
  }
  for (Eigen::Index k = 0; k < wall.size(); ++k)
    if (scratch.weight[k] > 0) P_k[k] /= scratch.weight[k];
  on_wall.setZero(3, wall.size());
  for (int i = 0; i < pairs.rows(); ++i) {
    const double volume_i = fluid.m[i] / fluid.rho[i];
    Eigen::Vector3d force_i = Eigen::Vector3d::Zero();
    double divergence = 0;
    for (int q = pairs.offset[static_cast<std::size_t>(i)]; q < pairs.offset[static_cast<std::size_t>(i) + 1]; ++q) {
      const int k = pairs.index[static_cast<std::size_t>(q)];
      const Eigen::Vector3d S_k = vertex_normal.col(k) / 6.0;
      const Eigen::Vector3d fik = -pressure_coupling_coefficient(volume_i, pressure[i], P_k[k], W[q]) * S_k;
      force_i += fik;
      on_wall.col(k) -= fik;
      divergence += W[q] * (fluid.v.col(i) - wall.v.col(k)).dot(S_k);
    }
    fluid_force.col(i) += force_i;
    drho_dt[i] += fluid.rho[i] * divergence;
  }
}

}  // namespace cellsim
