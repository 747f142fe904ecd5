#include "wall_fluid.hpp"

namespace cellsim {

void wall_fluid_forces(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const PairList& pairs,
                       const LennardJones& lj, Eigen::Matrix3Xd& fluid_force, Eigen::Matrix3Xd& on_wall) {
  on_wall.setZero(3, wall_x.cols());
  for (int i = 0; i < pairs.rows(); ++i) {
    const Eigen::Vector3d xi = fluid_x.col(i);
    Eigen::Vector3d force_i = Eigen::Vector3d::Zero();
    for (int q = pairs.offset[static_cast<std::size_t>(i)]; q < pairs.offset[static_cast<std::size_t>(i) + 1]; ++q) {
      const int k = pairs.index[static_cast<std::size_t>(q)];
      const Eigen::Vector3d xik = xi - wall_x.col(k);
      const Eigen::Vector3d fik = lj.f_of_r2(xik.squaredNorm()) * xik;
      force_i += fik;
      on_wall.col(k) -= fik;
    }
    fluid_force.col(i) += force_i;
  }
}

}  // namespace cellsim
