// Newton's method over a pure evaluation (newton_solver.hpp).
#include "engine/newton_solver.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace cellsim {
namespace {

// The inner solve stops at |r| <= kForcingTerm x |F|, or after kMaxConjugateGradients products; a
// product's probe moves no particle farther than kProbe_m. The shift starts at kLeastShift_N_m where it
// must and grows or shrinks by kShiftGrowth. A step is halved at most kMaxHalvings times; a full step
// that fell by kGoodRatio of the model's promise shrinks the shift.
constexpr double kForcingTerm = 0.1, kProbe_m = 1e-11;
constexpr double kLeastShift_N_m = 1e-2, kShiftGrowth = 4, kArmijo = 1e-4, kGoodRatio = 0.75, kRoundOff = 1e-12;
constexpr int kMaxHalvings = 10;
constexpr int kMaxConjugateGradients = 200;
constexpr int kRefactorAfterProducts = 20;

using Point = NewtonProblem::Point;
using Flat = Eigen::Map<const Eigen::VectorXd>;
Flat flat(const Eigen::Matrix3Xd& m) { return Flat(m.data(), m.size()); }
Eigen::Map<const Eigen::Matrix3Xd> as_positions(const Eigen::VectorXd& v) {
  return Eigen::Map<const Eigen::Matrix3Xd>(v.data(), 3, v.size() / 3);
}

double largest_force_N(const Eigen::Matrix3Xd& force) { return std::sqrt(force.colwise().squaredNorm().maxCoeff()); }
double longest_move_m(const Eigen::VectorXd& d) { return std::sqrt(as_positions(d).colwise().squaredNorm().maxCoeff()); }

struct Direction {
  Eigen::VectorXd d;
  double model_decrease_J = 0;  // F.d - d.H.d / 2, the quadratic model's promise
  bool negative_curvature = false;
  int products = 0;  // of H with a direction: force evaluations
};

// d solving (H + shift) d = F by preconditioned conjugate gradients (Steihaug). Every step goes downhill
// at first (F.d > 0): F.p > 0 for every CG direction (p.r_0 = p.r_k = r_k.z_k). The residual, the
// preconditioned residual and the products are all projected, so every step keeps the constraints.
Direction direction(NewtonProblem& problem, const Point& at, double shift_N_m, double max_move_m,
                    std::int64_t& evaluations, std::int64_t max_evaluations) {
  Direction out;
  const Eigen::VectorXd f = flat(at.force);
  out.d = Eigen::VectorXd::Zero(f.size());
  Eigen::VectorXd Hd = Eigen::VectorXd::Zero(f.size());  // H d, unshifted, for the model's decrease
  Eigen::VectorXd r = f, z = problem.precondition(r), Hp;
  problem.project(z);
  Eigen::VectorXd p = z;
  double rz = r.dot(z);
  for (int cg = 0; cg < kMaxConjugateGradients && evaluations < max_evaluations; ++cg) {
    const double probe = kProbe_m / p.cwiseAbs().maxCoeff();
    Hp = -(flat(problem.unconstrained_force(at.x + probe * as_positions(p))) - f) / probe;
    problem.project(Hp);
    ++evaluations;
    ++out.products;
    const double pHp = p.dot(Hp);
    if (!(pHp + shift_N_m * p.squaredNorm() > 0)) {  // downhill along p to the trust radius
      const double tau = max_move_m / longest_move_m(p);
      out.negative_curvature = true;
      out.model_decrease_J = f.dot(out.d + tau * p) - 0.5 * (out.d.dot(Hd) + 2 * tau * out.d.dot(Hp) + tau * tau * pHp);
      out.d += tau * p;
      return out;
    }
    const double alpha = rz / (pHp + shift_N_m * p.squaredNorm());
    out.d += alpha * p;
    Hd += alpha * Hp;
    r -= alpha * (Hp + shift_N_m * p);
    if (r.norm() <= kForcingTerm * f.norm()) break;
    z = problem.precondition(r);
    problem.project(z);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  out.model_decrease_J = f.dot(out.d) - 0.5 * out.d.dot(Hd);
  return out;
}

}  // namespace

NewtonResult minimise(NewtonProblem& problem, const Eigen::Matrix3Xd& x0, const NewtonSettings& settings) {
  NewtonResult out;
  Point now = problem.evaluate(x0);  // from the history the problem holds: x0 is where it was accepted
  ++out.evaluations;
  out.start = now;
  bool refactor = true;
  double shift_N_m = 0;
  while (true) {
    out.residual = largest_force_N(now.force) / now.load_N;
    if (out.residual <= settings.tolerance || out.evaluations >= settings.max_evaluations) break;
    if (refactor) problem.factor_at(now);
    Direction step = direction(problem, now, shift_N_m, settings.max_move_m, out.evaluations, settings.max_evaluations);
    refactor = step.negative_curvature || step.products > kRefactorAfterProducts;
    const double longest_m = longest_move_m(step.d);
    if (longest_m > settings.max_move_m) step.d *= settings.max_move_m / longest_m;
    const double first_order_J = flat(now.force).dot(step.d);
    const double round_off_J = kRoundOff * std::abs(now.potential_J);
    double length = 1;
    bool accepted = false;
    for (int halving = 0; halving <= kMaxHalvings && out.evaluations < settings.max_evaluations;
         ++halving, length *= 0.5) {
      Point trial = problem.evaluate(now.x + length * as_positions(step.d));
      ++out.evaluations;
      const double fall_J = now.potential_J - trial.potential_J;
      const bool downhill = fall_J >= kArmijo * length * first_order_J;
      // Within the potential's round-off, the largest force decides.
      const bool flat_and_better =
          std::abs(fall_J) <= round_off_J && largest_force_N(trial.force) < largest_force_N(now.force);
      if (!downhill && !flat_and_better) continue;
      if (!step.negative_curvature && halving == 0 && fall_J >= kGoodRatio * step.model_decrease_J)
        shift_N_m = shift_N_m / kShiftGrowth < kLeastShift_N_m ? 0.0 : shift_N_m / kShiftGrowth;
      else if (halving > 0)
        shift_N_m = std::max(kShiftGrowth * shift_N_m, kLeastShift_N_m);
      now = std::move(trial);
      problem.accept_last();
      accepted = true;
      break;
    }
    if (!accepted) shift_N_m = std::max(kShiftGrowth * shift_N_m, kLeastShift_N_m);
  }
  out.end = std::move(now);
  out.converged = out.residual <= settings.tolerance;
  return out;
}

}  // namespace cellsim
