// Bending, Eq 20: forces are -grad E_b (finite differences, rel. 1e-5), sum to zero, and E_b is
// zero for a flat hinge.
#include <gtest/gtest.h>

#include <random>

#include "geometry/hull.hpp"
#include "physics/bending.hpp"

using namespace cellsim;

namespace {

// A small closed cell with its vertices displaced at random, so hinges are bent by various angles.
struct BumpyCell {
  Eigen::Matrix3Xd x;
  WallMesh mesh;
  BumpyCell() {
    x = fibonacci_sphere(60, 10e-6);
    mesh = build_wall_mesh(x, convex_hull_triangles(x));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-0.6e-6, 0.6e-6);
    for (Eigen::Index i = 0; i < x.cols(); ++i) x.col(i) += Eigen::Vector3d(u(rng), u(rng), u(rng));
  }
};

}  // namespace

TEST(Bending, ForcesAreMinusGradientOfEnergy) {
  BumpyCell cell;
  const Bending bending(cell.mesh, 1e-10);
  Eigen::Matrix3Xd force = Eigen::Matrix3Xd::Zero(3, cell.x.cols());
  bending.add_forces(cell.x, force);
  const double eps = 1e-12;  // m: relative 1e-7 of the cell size
  double worst = 0;
  for (Eigen::Index i = 0; i < cell.x.cols(); ++i)
    for (int d = 0; d < 3; ++d) {
      Eigen::Matrix3Xd xp = cell.x, xm = cell.x;
      xp(d, i) += eps;
      xm(d, i) -= eps;
      const double fd = -(bending.energy(xp) - bending.energy(xm)) / (2 * eps);
      worst = std::max(worst, std::abs(fd - force(d, i)) / force.col(i).norm());
    }
  EXPECT_LT(worst, 1e-5);
}

TEST(Bending, ForcesSumToZeroAndFlatHingeHasNoEnergy) {
  BumpyCell cell;
  const Bending bending(cell.mesh, 1e-10);
  Eigen::Matrix3Xd force = Eigen::Matrix3Xd::Zero(3, cell.x.cols());
  bending.add_forces(cell.x, force);
  EXPECT_LT(force.rowwise().sum().norm(), 1e-12 * force.colwise().norm().maxCoeff());
  // Torque-free too: the energy is rotation invariant.
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < cell.x.cols(); ++i) torque += cell.x.col(i).cross(force.col(i));
  EXPECT_LT(torque.norm(), 1e-12 * 10e-6 * force.colwise().norm().maxCoeff());

  WallMesh flat;
  flat.triangles = {{0, 1, 2}, {1, 0, 3}};
  flat.hinges = {{0, 1, 2, 3, 0, 1}};
  flat.rest_length_m = {1.0};
  Eigen::Matrix3Xd square(3, 4);
  square << 0, 1, 0, 1,  //
      0, 0, 1, -1,       //
      0, 0, 0, 0;
  // Triangles (0,1,2) and (1,0,3) are coplanar with the same orientation.
  EXPECT_NEAR(Bending(flat, 1e-10).energy(square), 0.0, 1e-25);
}
