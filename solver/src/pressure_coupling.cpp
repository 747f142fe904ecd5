#include "pressure_coupling.hpp"

namespace cellsim {

// Pass 1: W of every pair, and the Shepard sums of P_k; pass 2: the pair forces.
void pressure_coupling_forces(const Eigen::Matrix3Xd& fluid_x, const Eigen::VectorXd& volume,
                              const Eigen::VectorXd& pressure, const Eigen::Matrix3Xd& wall_x,
                              const Eigen::Matrix3Xd& area_vector, const PairList& pairs,
                              const CubicSplineKernel& kernel, Eigen::Matrix3Xd& fluid_force,
                              Eigen::Matrix3Xd& on_wall, Eigen::VectorXd& pair_W, Eigen::VectorXd& wall_pressure,
                              const Eigen::Matrix3Xd& fluid_v, const Eigen::VectorXd& rho, const Eigen::Matrix3Xd& wall_v,
                              Eigen::VectorXd& drho_dt) {
  const auto n_wall = wall_x.cols();
  pair_W.resize(static_cast<Eigen::Index>(pairs.index.size()));
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(n_wall);
  wall_pressure.setZero(n_wall);
  for (int i = 0; i < pairs.rows(); ++i) {
    const Eigen::Vector3d xi = fluid_x.col(i);
    for (int q = pairs.offset[static_cast<std::size_t>(i)]; q < pairs.offset[static_cast<std::size_t>(i) + 1]; ++q) {
      const int k = pairs.index[static_cast<std::size_t>(q)];
      pair_W[q] = kernel.W((xi - wall_x.col(k)).norm());
      weight[k] += volume[i] * pair_W[q];
      wall_pressure[k] += volume[i] * pair_W[q] * pressure[i];
    }
  }
  for (Eigen::Index k = 0; k < n_wall; ++k)
    if (weight[k] > 0) wall_pressure[k] /= weight[k];
  on_wall.setZero(3, n_wall);
  for (int i = 0; i < pairs.rows(); ++i) {
    Eigen::Vector3d force_i = Eigen::Vector3d::Zero();
    double divergence = 0;
    for (int q = pairs.offset[static_cast<std::size_t>(i)]; q < pairs.offset[static_cast<std::size_t>(i) + 1]; ++q) {
      const int k = pairs.index[static_cast<std::size_t>(q)];
      divergence += pair_W[q] * (fluid_v.col(i) - wall_v.col(k)).dot(area_vector.col(k));
      const Eigen::Vector3d fik =
          -pressure_coupling_coefficient(volume[i], pressure[i], wall_pressure[k], pair_W[q]) * area_vector.col(k);
      force_i += fik;
      on_wall.col(k) -= fik;
    }
    fluid_force.col(i) += force_i;
    drho_dt[i] += rho[i] * divergence;
  }
}

}  // namespace cellsim
