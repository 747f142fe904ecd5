// The quasi-static scheme (quasi_static.hpp).
#include "engine/quasi_static.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "engine/simulation.hpp"
#include "physics/wall_stiffness.hpp"

#include <Eigen/SparseCholesky>

namespace cellsim {
namespace {

// FIRE's constants (Bitzek et al. 2006); its pseudo-step starts at half the wall springs' limit and grows
// up to it (the limit is a bound on the stiffest mode: step_checks.hpp).
constexpr double kAlphaStart = 0.1, kAlphaShrink = 0.99, kStepGrow = 1.1, kStepShrink = 0.5;
constexpr int kStepsBeforeGrowing = 5;
constexpr double kFirstStepOverLimit = 0.5;
constexpr double kLeastPressureLoad_Pa = 1e3;  // the load scale of a cell without turgor
// Newton's: the inner solve stops at |r| <= this x |F|, or after so many products; a product's probe
// moves no particle farther than kProbe_m; the step is halved at most kMaxHalvings times; where Newton
// stalls FIRE runs kFireIterations. The springs' stiffness gets kStiffnessShift_N_m on its diagonal.
constexpr double kForcingTerm = 0.1, kProbe_m = 1e-11, kStiffnessShift_N_m = 1e-2;
constexpr int kMaxConjugateGradients = 200, kMaxHalvings = 8;
constexpr std::int64_t kFireIterations = 2000;

// What a wall particle carries: max(P_T0, the largest |P| of a cell) x the mean area a wall particle owns.
double pressure_load_N(const Simulation& sim) {
  double pressure = std::max(sim.params().turgor_Pa, kLeastPressureLoad_Pa);
  for (double P : sim.cell_mean_fluid_pressure_Pa()) pressure = std::max(pressure, std::abs(P));
  return pressure * sim.surface().area_m2 / static_cast<double>(sim.state().wall.size());
}

// FIRE from the wall's positions now, for at most max_iterations force evaluations: steer the velocity
// toward the force while going downhill, stop dead when uphill. Its losses are the kinetic energy the
// steering and the stops take, the wall damping at the pseudo-velocities, and what is left at the end.
Equilibrium fire(Simulation& sim, double tolerance, std::int64_t max_iterations) {
  Equilibrium eq;
  WallParticles& w = sim.mutable_state().wall;
  const double mass = w.mass_kg, limit = sim.wall_spring_limit_s();
  double step = kFirstStepOverLimit * limit, alpha = kAlphaStart, last_step = 0;
  int downhill = 0;
  w.v.setZero();
  for (;; ++eq.iterations) {
    sim.refresh_rates();
    const Eigen::Matrix3Xd& force = sim.wall_force();
    eq.loss_J += last_step * sim.power_W()[kDampingLoss];  // Eq 16 at the pseudo-velocities of the last step
    eq.residual = std::sqrt(force.colwise().squaredNorm().maxCoeff()) / pressure_load_N(sim);
    if (eq.residual <= tolerance || eq.iterations >= max_iterations) break;
    const double kinetic_before = 0.5 * mass * w.v.squaredNorm();
    if (force.cwiseProduct(w.v).sum() > 0) {
      w.v = (1 - alpha) * w.v + (alpha * w.v.norm() / force.norm()) * force;
      if (++downhill > kStepsBeforeGrowing) step = std::min(step * kStepGrow, limit), alpha *= kAlphaShrink;
    } else {
      w.v.setZero();
      step *= kStepShrink;
      alpha = kAlphaStart;
      downhill = 0;
    }
    eq.loss_J += kinetic_before - 0.5 * mass * w.v.squaredNorm();
    w.v += (step / mass) * force;
    w.x += step * w.v;
    last_step = step;
  }
  eq.loss_J += 0.5 * mass * w.v.squaredNorm();  // at equilibrium the wall is brought to rest
  w.v.setZero();
  eq.converged = eq.residual <= tolerance;
  return eq;
}

using Flat = Eigen::Map<const Eigen::VectorXd>;
Flat flat(const Eigen::Matrix3Xd& m) { return Flat(m.data(), m.size()); }

// The wall's forces with its particles at x (one force evaluation; the rates follow).
const Eigen::Matrix3Xd& forces_at(Simulation& sim, const Eigen::Matrix3Xd& x) {
  sim.mutable_state().wall.x = x;
  sim.refresh_rates();
  return sim.wall_force();
}

}  // namespace

// Inexact Newton: the step d solves H d = F (H = -dF/dx) by conjugate gradients, H p by a difference of
// forces, preconditioned with the springs' stiffness (wall_stiffness.hpp), which holds the stiff part;
// a direction of negative curvature (a fold forming) ends the inner solve (Steihaug). The step is taken
// in full or halved until |F| falls. Where Newton stalls, FIRE takes over for a while. The loss is the
// work the forces did along the path (trapezoid per step: what the stored energy lost).
Equilibrium relax_wall(Simulation& sim, double tolerance, std::int64_t max_iterations) {
  Equilibrium eq;
  WallParticles& w = sim.mutable_state().wall;
  w.v.setZero();
  Eigen::Matrix3Xd x0 = w.x, F0 = forces_at(sim, x0), x1, F1;
  ++eq.iterations;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> spring_stiffness;
  bool factored = false;
  while (true) {
    eq.residual = std::sqrt(F0.colwise().squaredNorm().maxCoeff()) / pressure_load_N(sim);
    if (eq.residual <= tolerance || eq.iterations >= max_iterations) break;
    if (!factored) {
      spring_stiffness.compute(wall_spring_stiffness(x0, sim.mesh(), sim.bond_law(), sim.contraction_ramp(),
                                                     sim.plate_law(), sim.state().plates, kStiffnessShift_N_m));
      factored = spring_stiffness.info() == Eigen::Success;
    }
    Eigen::VectorXd d = Eigen::VectorXd::Zero(F0.size());
    if (factored) {
      const Eigen::VectorXd f = flat(F0);
      Eigen::VectorXd r = f, z = spring_stiffness.solve(r), p = z, Hp;
      double rz = r.dot(z);
      for (int cg = 0; cg < kMaxConjugateGradients && eq.iterations < max_iterations; ++cg) {
        const double probe = kProbe_m / p.cwiseAbs().maxCoeff();
        Eigen::Matrix3Xd moved = x0 + probe * Eigen::Map<const Eigen::Matrix3Xd>(p.data(), 3, x0.cols());
        Hp = -(flat(forces_at(sim, moved)) - f) / probe;
        ++eq.iterations;
        const double curvature = p.dot(Hp);
        if (!(curvature > 0)) {
          if (cg == 0) d = p;
          break;
        }
        const double alpha = rz / curvature;
        d += alpha * p;
        r -= alpha * Hp;
        if (r.norm() <= kForcingTerm * f.norm()) break;
        z = spring_stiffness.solve(r);
        const double rz_next = r.dot(z);
        p = z + (rz_next / rz) * p;
        rz = rz_next;
      }
    }
    bool accepted = false;
    double step = 1;
    for (int halving = 0; factored && halving < kMaxHalvings && eq.iterations < max_iterations; ++halving, step *= 0.5) {
      x1 = x0 + step * Eigen::Map<const Eigen::Matrix3Xd>(d.data(), 3, x0.cols());
      F1 = forces_at(sim, x1);
      ++eq.iterations;
      if (F1.norm() < (1 - 1e-4 * step) * F0.norm()) {
        accepted = true;
        break;
      }
    }
    if (accepted) {
      eq.loss_J += 0.5 * (F0 + F1).cwiseProduct(x1 - x0).sum();
      x0 = x1;
      F0 = F1;
      continue;
    }
    // Newton stalled (a fold, a contact switching): FIRE from x0 for a while, then Newton again.
    w.x = x0;
    const Equilibrium fired = fire(sim, tolerance, std::min(kFireIterations, max_iterations - eq.iterations));
    eq.iterations += fired.iterations + 1;
    eq.loss_J += fired.loss_J;
    x0 = w.x;
    F0 = sim.wall_force();
    factored = false;
  }
  forces_at(sim, x0);  // the rates at the equilibrium (the probes moved the particles)
  eq.converged = eq.residual <= tolerance;
  return eq;
}

void quasi_static_step(Simulation& sim) {
  const Params& p = sim.params();
  State& s = sim.mutable_state();
  // The loads move at fixed particles: what that changes of the stored energy is put in (plate, drive).
  const EnergyValues before = sim.energy_terms_now();
  sim.advance_loads(p.dt_s);
  sim.refresh_rates();  // the surface at the particles now (a periodic slab's period moved them)
  const EnergyValues after = sim.energy_terms_now();
  const double plate_J = after[kPlateSprings] - before[kPlateSprings];
  s.energy.integral[kPlateWork] += plate_J;
  s.energy.integral[kDrive] += stored_energy_J(after) - stored_energy_J(before) - plate_J;

  CavityFluid& cavity = sim.cavity_fluid();
  cavity.begin_increment(s, sim.fluid_context(), p.dt_s);
  const Equilibrium eq = relax_wall(sim, p.equilibrium_tolerance, p.relaxation_max_iterations);
  s.energy.integral[kRelaxationLoss] += eq.loss_J;
  s.energy.integral[kMassTransfer] += cavity.end_increment(s, sim.fluid_context());
  if (!eq.converged) {
    std::ostringstream msg;
    msg << "step " << s.step + 1 << " (t = " << s.time_s * 1e6 << " us, "
        << (s.stage == Stage::Drying ? "drying" : "compression") << "): the wall did not reach equilibrium within "
        << "time.relaxation_max_iterations = " << p.relaxation_max_iterations << " (largest force "
        << eq.residual << " of its pressure load, time.equilibrium_tolerance = " << p.equilibrium_tolerance
        << "); give more iterations, a looser tolerance or a smaller time.dt_ns";
    throw NumericalFailure(msg.str());
  }
  sim.refresh_rates();  // the rates at the increment's masses
  sim.finish_step();
}

}  // namespace cellsim
