// Newton's method over a pure evaluation (engine/newton_solver.hpp), alone on known functions: on a
// quadratic it is exact in one step; on a double well started on its hump, where the curvature is
// negative, it goes downhill to the minimum the force points to, not to the maximum where the force
// also vanishes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "engine/newton_solver.hpp"

using namespace cellsim;

namespace {

constexpr int kParticles = 10;
constexpr double kScale_m = 1e-5;  // positions of a cell's size, so a probe of 1e-11 m resolves the forces

Eigen::VectorXd flat(const Eigen::Matrix3Xd& x) { return Eigen::Map<const Eigen::VectorXd>(x.data(), x.size()); }

// Pi(x) = (x - c).A (x - c) / 2 over the stacked positions, A a chain of springs k between neighbours and
// k_i to c: symmetric positive definite. The preconditioner is A itself.
class Quadratic final : public NewtonProblem {
 public:
  Quadratic() : A_(Eigen::MatrixXd::Zero(3 * kParticles, 3 * kParticles)), c_(3, kParticles) {
    const int n = 3 * kParticles;
    for (int i = 0; i < n; ++i) {
      A_(i, i) = 2.0 + 0.1 * (i % 7);  // N/m
      if (i + 1 < n) A_(i, i + 1) = A_(i + 1, i) = -0.9;
    }
    for (int k = 0; k < kParticles; ++k)
      c_.col(k) = kScale_m * Eigen::Vector3d(std::sin(k), std::cos(2.0 * k), 0.3 * k);
    llt_.compute(A_);
  }
  const Eigen::Matrix3Xd& minimum() const { return c_; }

  Point evaluate(const Eigen::Matrix3Xd& x) override {
    Point point{x, unconstrained_force(x)};
    const Eigen::VectorXd d = flat(x - c_);
    point.potential_J = 0.5 * d.dot(A_ * d);
    point.load_N = 1e-6;
    return point;
  }
  const Eigen::Matrix3Xd& unconstrained_force(const Eigen::Matrix3Xd& x) override {
    const Eigen::VectorXd f = -A_ * flat(x - c_);
    force_ = Eigen::Map<const Eigen::Matrix3Xd>(f.data(), 3, kParticles);
    return force_;
  }
  void accept_last() override {}
  void factor_at(const Point&) override { ++factorings; }
  Eigen::VectorXd precondition(const Eigen::VectorXd& r) const override { return llt_.solve(r); }

  int factorings = 0;

 private:
  Eigen::MatrixXd A_;
  Eigen::Matrix3Xd c_, force_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
};

// Each particle in a double well along z, Pi = a (z^2 - L^2)^2 / (4 L^2), and held to the axis by springs
// k (x^2 + y^2) / 2. Its curvature along z, a (3 z^2 - L^2) / L^2, is negative on the hump |z| < L / sqrt 3;
// the force there points away from z = 0, a maximum where it vanishes too. The preconditioner is the
// diagonal a (along z) and k: positive, as the wall's is.
class DoubleWell final : public NewtonProblem {
 public:
  static constexpr double kWell_m = 1e-6, kA_N_m = 1.0, kSpring_N_m = 0.5;

  Point evaluate(const Eigen::Matrix3Xd& x) override {
    Point point{x, unconstrained_force(x)};
    for (int k = 0; k < x.cols(); ++k) {
      const double z = x(2, k);
      point.potential_J += kA_N_m * std::pow(z * z - kWell_m * kWell_m, 2) / (4 * kWell_m * kWell_m) +
                           0.5 * kSpring_N_m * (x(0, k) * x(0, k) + x(1, k) * x(1, k));
    }
    point.load_N = kA_N_m * kWell_m;
    return point;
  }
  const Eigen::Matrix3Xd& unconstrained_force(const Eigen::Matrix3Xd& x) override {
    force_.resize(3, x.cols());
    for (int k = 0; k < x.cols(); ++k) {
      const double z = x(2, k);
      force_.col(k) = Eigen::Vector3d(-kSpring_N_m * x(0, k), -kSpring_N_m * x(1, k),
                                      -kA_N_m * z * (z * z - kWell_m * kWell_m) / (kWell_m * kWell_m));
    }
    return force_;
  }
  void accept_last() override { ++accepted; }
  void factor_at(const Point&) override {}
  Eigen::VectorXd precondition(const Eigen::VectorXd& r) const override {
    Eigen::VectorXd z = r;
    for (Eigen::Index i = 0; i < z.size(); ++i) z[i] /= (i % 3 == 2 ? kA_N_m : kSpring_N_m);
    return z;
  }

  int accepted = 0;

 private:
  Eigen::Matrix3Xd force_;
};

}  // namespace

// Exact on a quadratic with its own Hessian as the preconditioner: the first evaluation, one product and one
// trial, which lands on the minimum to the difference quotient's round-off.
TEST(NewtonSolver, IsExactInOneStepOnAQuadratic) {
  Quadratic problem;
  Eigen::Matrix3Xd x0 = problem.minimum();
  for (int k = 0; k < kParticles; ++k) x0.col(k) += 1e-6 * Eigen::Vector3d(std::cos(3.0 * k), 1.0, -0.5);
  const NewtonResult result = minimise(problem, x0, {1e-6, 100, kScale_m});
  ASSERT_TRUE(result.converged);
  EXPECT_EQ(result.evaluations, 3);
  EXPECT_EQ(problem.factorings, 1);
  EXPECT_LT((result.end.x - problem.minimum()).cwiseAbs().maxCoeff(), 1e-14);  // 1e-8 of the start's offset
  EXPECT_LT(result.end.potential_J, 1e-12 * result.start.potential_J);
  EXPECT_NEAR(result.residual, (result.end.force.colwise().norm().maxCoeff()) / 1e-6, 1e-12);
}

// A step limited by the trust radius still gets there, each accepted step downhill.
TEST(NewtonSolver, ReachesTheQuadraticsMinimumThroughItsTrustRadius) {
  Quadratic problem;
  Eigen::Matrix3Xd x0 = problem.minimum();
  x0.row(2).array() += 4e-6;
  const NewtonResult result = minimise(problem, x0, {1e-6, 100, 0.5e-6});  // 8 steps of the radius at least
  ASSERT_TRUE(result.converged) << result.residual;
  EXPECT_GE(result.evaluations, 8 * 2);
  EXPECT_LT((result.end.x - problem.minimum()).cwiseAbs().maxCoeff(), 1e-12);
}

// Started on the hump of a double well, where the model's curvature is negative, the step follows that
// direction downhill (Steihaug) and ends in the well the force points to (z = +L), not at the maximum
// z = 0 where the force vanishes as well; every accepted point lies below the one before.
TEST(NewtonSolver, GoesDownhillFromAFoldToTheMinimumNotTheMaximum) {
  DoubleWell problem;
  const double L = DoubleWell::kWell_m;
  Eigen::Matrix3Xd x0(3, kParticles);
  for (int k = 0; k < kParticles; ++k) x0.col(k) = Eigen::Vector3d(0.5 * L, -0.2 * L, (0.05 + 0.01 * k) * L);
  const NewtonResult result = minimise(problem, x0, {1e-9, 400, 0.25 * L});
  ASSERT_TRUE(result.converged) << result.residual;
  for (int k = 0; k < kParticles; ++k) {
    EXPECT_NEAR(result.end.x(2, k), L, 1e-8 * L) << "particle " << k;
    EXPECT_NEAR(result.end.x(0, k), 0.0, 1e-8 * L);
  }
  EXPECT_LT(result.end.potential_J, result.start.potential_J);
  EXPECT_GT(problem.accepted, 0);
  EXPECT_LT(result.evaluations, 200);
}

// Out of evaluations it stops where it is and says so: not converged, the residual of its last point.
TEST(NewtonSolver, StopsUnconvergedAtItsEvaluationLimit) {
  DoubleWell problem;
  Eigen::Matrix3Xd x0 = Eigen::Matrix3Xd::Constant(3, kParticles, 0.1 * DoubleWell::kWell_m);
  const NewtonResult result = minimise(problem, x0, {1e-12, 3, 0.25 * DoubleWell::kWell_m});
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.evaluations, 3);
  EXPECT_GT(result.residual, 1e-12);
}
