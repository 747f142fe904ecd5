#pragma once
// Newton's method for a minimum of a potential over the positions of n particles (the quasi-static
// relaxation's, quasi_static.hpp; tested alone on known functions in test_newton_solver), given a pure
// evaluation of a point: its force (minus the potential's gradient) and its potential.
//
// Each step: a direction by conjugate gradients on differences of forces, H p = -(F(x + e p) - F(x)) / e,
// preconditioned by the problem (Steihaug's truncated CG: it stops at |r| <= kForcingTerm |F|; where it
// meets a direction of negative curvature, a fold forming, the step follows it downhill to the trust
// radius); a shift (Levenberg-Marquardt: a spring to the last accepted point) where the quadratic model
// fails; a backtracking line search that halves the step until the potential falls by kArmijo of its
// first-order promise F.d, or, within the potential's round-off, until the largest force falls. No
// particle moves farther than max_move_m in one step. The preconditioner is factored afresh at a step's
// start where the last step's CG took more than kRefactorAfterProducts products or met negative
// curvature: where the potential folds, the stiffness of the start no longer holds.
#include <cstdint>

#include <Eigen/Core>

namespace cellsim {

class NewtonProblem {
 public:
  struct Point {
    Eigen::Matrix3Xd x, force;  // force within the problem's constraints (project)
    double potential_J = 0;
    double load_N = 1;          // the force scale of the equilibrium test at this point
    double dissipated_J = 0;    // what the problem's history took on the way to this point (0 if none)
  };
  virtual ~NewtonProblem() = default;

  // The point at x, from the last accepted point: the same x gives the same point, whatever was
  // evaluated in between.
  virtual Point evaluate(const Eigen::Matrix3Xd& x) = 0;
  // The forces at x as evaluate gives them before the constraints, for the products H p.
  virtual const Eigen::Matrix3Xd& unconstrained_force(const Eigen::Matrix3Xd& x) = 0;
  // The point evaluated last is accepted: what its evaluation wrote of the problem's history (plastic
  // sliders, damage) is where the next evaluations start.
  virtual void accept_last() = 0;
  // The preconditioner factored at a point, and z = M^-1 r with it.
  virtual void factor_at(const Point& point) = 0;
  virtual Eigen::VectorXd precondition(const Eigen::VectorXd& r) const = 0;
  // v less its part along what the constraints hold, in place (stacked x, y, z per particle); none here.
  virtual void project(Eigen::Ref<Eigen::VectorXd>) const {}
};

struct NewtonSettings {
  double tolerance = 1e-6;              // equilibrium: largest particle force <= tolerance x the point's load_N
  std::int64_t max_evaluations = 1000;  // of the problem's forces, products and line search included
  double max_move_m = 0;                // the trust radius: the farthest one particle moves in a step
};

struct NewtonResult {
  NewtonProblem::Point start, end;
  std::int64_t evaluations = 0;
  double residual = 0;  // largest particle force / load_N, at the end
  bool converged = false;
};

// Minimises the problem's potential from x0, the point its history was accepted at (its evaluation
// accepts nothing: the history is the problem's as it was).
NewtonResult minimise(NewtonProblem& problem, const Eigen::Matrix3Xd& x0, const NewtonSettings& settings);

}  // namespace cellsim
