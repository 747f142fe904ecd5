// Cubic spline kernel, Eq 5 as corrected in model.md §2: moments on a fine lattice.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Core>

#include "physics/kernel.hpp"

using cellsim::CubicSplineKernel;

namespace {

// Sums f(x) dx^3 over a cubic lattice of spacing h/8 offset from the origin by a fixed shift.
template <class F>
double lattice_sum(double h, F f) {
  const double dx = h / 8.0;
  const Eigen::Vector3d shift(0.31 * dx, 0.17 * dx, 0.43 * dx);
  double sum = 0;
  for (int i = -17; i <= 17; ++i)
    for (int j = -17; j <= 17; ++j)
      for (int k = -17; k <= 17; ++k) sum += f(Eigen::Vector3d(i * dx, j * dx, k * dx) + shift) * dx * dx * dx;
  return sum;
}

}  // namespace

TEST(Kernel, IntegratesToOne) {
  const double h = 6.8e-6;
  const CubicSplineKernel W(h);
  EXPECT_NEAR(lattice_sum(h, [&](const Eigen::Vector3d& x) { return W.W(x.norm()); }), 1.0, 1e-3);
}

TEST(Kernel, FirstMomentsVanishAndSecondIsMinusOne) {
  // PySPH-style moment tests: int x W = 0, int grad W = 0, int x dW/dx = -1.
  const double h = 2.0;
  const CubicSplineKernel W(h);
  const auto grad = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return W.dW_dr_over_r(x.norm()) * x; };
  EXPECT_NEAR(lattice_sum(h, [&](const Eigen::Vector3d& x) { return x.x() * W.W(x.norm()); }), 0.0, 1e-3 * h);
  EXPECT_NEAR(lattice_sum(h, [&](const Eigen::Vector3d& x) { return grad(x).y(); }), 0.0, 1e-3 / h);
  EXPECT_NEAR(lattice_sum(h, [&](const Eigen::Vector3d& x) { return x.z() * grad(x).z(); }), -1.0, 1e-3);
}

TEST(Kernel, ValuesAtTheCentreAndContinuityAtTheBranches) {
  // W(0) = 3/(2 pi h^3) * 2/3 = 1/(pi h^3); both branches give 1/6 at s = 1 and 0 at s = 2.
  const double h = 1.5, norm = 3.0 / (2.0 * M_PI * h * h * h);
  const CubicSplineKernel W(h);
  EXPECT_NEAR(W.W(0.0), 1.0 / (M_PI * h * h * h), 1e-15);
  EXPECT_NEAR(W.W(h * (1 - 1e-12)), norm / 6.0, 1e-12);
  EXPECT_NEAR(W.W(h * (1 + 1e-12)), norm / 6.0, 1e-12);
  EXPECT_NEAR(W.W(2 * h * (1 - 1e-9)), 0.0, 1e-12);
  EXPECT_NEAR(W.dW_dr(h * (1 - 1e-12)), W.dW_dr(h * (1 + 1e-12)), 1e-10);  // C1 at s = 1
}

TEST(Kernel, GradientIsTheFiniteDifferenceGradientOfW) {
  // grad_i W_ij = (1/r dW/dr) x_ij, compared component by component with central differences of
  // W(|x|) in 3-D: catches a wrong 1/r, sign or branch in the gradient the pair loop uses.
  const CubicSplineKernel W(1.5);
  for (double r : {0.1, 0.7, 1.4, 1.6, 2.2, 2.9}) {
    const Eigen::Vector3d x = r * Eigen::Vector3d(0.48, -0.6, 0.64);
    const Eigen::Vector3d grad = W.dW_dr_over_r(x.norm()) * x;
    const double eps = 1e-6;
    for (int d = 0; d < 3; ++d) {
      const Eigen::Vector3d e = eps * Eigen::Vector3d::Unit(d);
      const double fd = (W.W((x + e).norm()) - W.W((x - e).norm())) / (2 * eps);
      EXPECT_NEAR(grad[d], fd, 1e-7) << "r " << r << " component " << d;
    }
    EXPECT_NEAR(W.dW_dr(r), (W.W(r + eps) - W.W(r - eps)) / (2 * eps), 1e-6) << r;
    EXPECT_LT(W.dW_dr(r), 0.0) << r;  // W decreases monotonically inside its support
  }
  EXPECT_EQ(W.W(3.0), 0.0);
  EXPECT_EQ(W.dW_dr(3.0), 0.0);
}

TEST(Kernel, FourLanesGiveTheGradientOfEachDistance) {
  const CubicSplineKernel W(1.5);
  const double r[8] = {0.0, 0.4, 1.4999, 1.5, 2.2, 2.9999, 3.0, 7.0};
  for (int k = 0; k < 8; k += 4) {
    const cellsim::simd::double4 lanes = W.dW_dr_over_r(cellsim::simd::double4{r[k], r[k + 1], r[k + 2], r[k + 3]});
    for (int l = 0; l < 4; ++l) EXPECT_NEAR(lanes[l], W.dW_dr_over_r(r[k + l]), 1e-15 * std::abs(W.dW_dr_over_r(0.0))) << r[k + l];
  }
  EXPECT_EQ(W.dW_dr_over_r(cellsim::simd::double4{3.0, 4.0, 1e30, 1e200})[3], 0.0);  // beyond the support
}

TEST(Kernel, FourLanesGiveWOfEachDistance) {
  const CubicSplineKernel W(1.5);
  const double r[8] = {0.0, 0.4, 1.4999, 1.5, 2.2, 2.9999, 3.0, 7.0};
  for (int k = 0; k < 8; k += 4) {
    const cellsim::simd::double4 lanes = W.W(cellsim::simd::double4{r[k], r[k + 1], r[k + 2], r[k + 3]});
    for (int l = 0; l < 4; ++l) EXPECT_NEAR(lanes[l], W.W(r[k + l]), 1e-15 * W.W(0.0)) << r[k + l];
  }
  EXPECT_EQ(W.W(cellsim::simd::double4{3.0, 4.0, 1e30, 1e200})[3], 0.0);  // beyond the support
}
