#include "wall_fluid.hpp"

namespace cellsim {

// Pass 1 gathers r^2 of every listed pair; pass 2 evaluates f(r) over that flat array (a loop the
// compiler vectorises: it holds the divisions); pass 3 applies f x_ik to both particles.
void wall_fluid_forces(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const PairList& pairs,
                       const LennardJones& lj, Eigen::Matrix3Xd& fluid_force, Eigen::Matrix3Xd& on_wall,
                       Eigen::VectorXd& pair_f) {
  on_wall.setZero(3, wall_x.cols());
  pair_f.resize(static_cast<Eigen::Index>(pairs.index.size()));
  double* f = pair_f.data();
  for (int i = 0; i < pairs.rows(); ++i) {
    const Eigen::Vector3d xi = fluid_x.col(i);
    for (int q = pairs.offset[static_cast<std::size_t>(i)]; q < pairs.offset[static_cast<std::size_t>(i) + 1]; ++q)
      f[q] = (xi - wall_x.col(pairs.index[static_cast<std::size_t>(q)])).squaredNorm();
  }
  for (Eigen::Index q = 0; q < pair_f.size(); ++q) f[q] = lj.f_of_r2(f[q]);
  for (int i = 0; i < pairs.rows(); ++i) {
    const Eigen::Vector3d xi = fluid_x.col(i);
    Eigen::Vector3d force_i = Eigen::Vector3d::Zero();
    for (int q = pairs.offset[static_cast<std::size_t>(i)]; q < pairs.offset[static_cast<std::size_t>(i) + 1]; ++q) {
      const int k = pairs.index[static_cast<std::size_t>(q)];
      const Eigen::Vector3d fik = f[q] * (xi - wall_x.col(k));
      force_i += fik;
      on_wall.col(k) -= fik;
    }
    fluid_force.col(i) += force_i;
  }
}

}  // namespace cellsim
