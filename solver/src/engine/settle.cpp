#include "engine/settle.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "engine/measures.hpp"
#include "engine/quasi_static.hpp"
#include "engine/simulation.hpp"

namespace cellsim {
namespace {

// FIRE's constants (Bitzek et al. 2006), and ours:
constexpr double kAlphaStart = 0.1, kAlphaShrink = 0.99, kStepGrow = 1.1, kStepShrink = 0.5;
constexpr int kStepsBeforeGrowing = 5;
constexpr double kMaxStepOverDt = 100;  // pseudo-step up to 100 dt (0.1 us at the default dt)
// The wall is ~1e5 times stiffer per unit mass than the fluid's LJ layer (wall springs: dt limit
// ~1.5 ns; LJ layer: period ~5 us). Minimisation may choose any masses: a wall pseudo-mass this much
// larger brings both to one time scale, so the pseudo-step can grow to kMaxStepOverDt.
constexpr double kWallPseudoMassScale = 2e5;
constexpr double kMaxMoveOverSpacing = 0.01;  // no particle moves more than 1 % of dx in one pseudo-step
constexpr int kMassUpdateEvery = 50;          // pseudo-steps between mass rescalings

// A closed cell (cavity_fluid.hpp) at rest: its wall relaxed under the fresh turgor held (drained, P = P_T0),
// then each cell's mass rho0 times the volume it encloses (quasi_static.hpp's relaxation).
SettleReport settle_closed_cells(Simulation& sim, IncrementFluid& increments, std::int64_t max_iterations) {
  SettleReport report;
  const double mass_before = sim.fluid().mass_kg(sim.state());
  const double volume_before = sim.surface().volume_m3;
  if (max_iterations > 0) {
    increments.begin_increment(sim.state(), sim.fluid_context(), INFINITY);
    const Equilibrium eq = relax_wall(sim, increments, sim.params().equilibrium_tolerance, max_iterations);
    increments.end_increment(sim.mutable_state(), sim.fluid_context());
    report.iterations = eq.iterations;
    report.residual = eq.residual;
    report.converged = eq.converged;
  }
  sim.start_at_rest();
  report.mass_ratio = sim.fluid().mass_kg(sim.state()) / mass_before;
  report.volume_ratio = sim.surface().volume_m3 / volume_before;
  return report;
}

}  // namespace

SettleReport settle(Simulation& sim, std::int64_t max_iterations, double tolerance) {
  // A fluid with increments (a closed cell) settles by the quasi-static relaxation; one of particles by FIRE.
  if (IncrementFluid* increments = sim.fluid_increments()) return settle_closed_cells(sim, *increments, max_iterations);
  SettleReport report;
  State& s = sim.mutable_state();
  auto& f = s.fluid;
  auto& w = s.wall;
  const double mass_before = f.m.sum();
  const double volume_before = wall_surface(w.x, sim.mesh()).volume_m3;
  if (max_iterations > 0) {
    const double rho0 = sim.params().fluid_density_kg_m3;
    const double dx = std::cbrt(f.m.mean() / rho0);  // particle spacing the masses imply
    // Acceleration of a boundary particle under the fresh turgor: the scale the residual is judged by.
    const double acceleration_scale = std::max(sim.turgor_Pa(), 1e3) / (rho0 * dx);
    const double max_step = kMaxStepOverDt * sim.params().dt_s;
    double step = sim.params().dt_s, alpha = kAlphaStart;
    int uphill_free = 0;
    f.v.setZero();
    w.v.setZero();
    Eigen::Matrix3Xd af, aw;
    for (;; ++report.iterations) {
      f.rho.setConstant(rho0);  // every particle at P = P_T0, where Eq 11 holds it at rest
      sim.refresh_rates();
      if (report.iterations % kMassUpdateEvery == kMassUpdateEvery - 1) {
        // The wall-pressure closure's target, reached at once: the push on the wall scales as m^2.
        const std::vector<double> mean_pressure = sim.cell_mean_fluid_pressure_Pa();
        const CellRanges& cells = sim.cells();
        for (int c = 0; c < cells.count(); ++c) {
          const double ratio = sim.cell_wall_pressure_Pa()[c] / mean_pressure[c];
          if (ratio > 0) f.m.segment(cells.fluid[c], cells.fluid_count(c)) *= 1.0 / std::sqrt(ratio);
        }
      }
      af = sim.fluid_force().array().rowwise() / f.m.transpose().array();
      aw = sim.wall_force() / (w.mass_kg * kWallPseudoMassScale);
      report.residual = af.colwise().norm().maxCoeff() / acceleration_scale;
      if (report.residual <= tolerance || report.iterations >= max_iterations) break;
      // FIRE: steer the velocity toward the force while going downhill; stop dead when uphill.
      const double power = af.cwiseProduct(f.v).sum() + aw.cwiseProduct(w.v).sum();
      if (power > 0) {
        const double mix = alpha * std::sqrt((f.v.squaredNorm() + w.v.squaredNorm()) /
                                             (af.squaredNorm() + aw.squaredNorm()));
        f.v = (1 - alpha) * f.v + mix * af;
        w.v = (1 - alpha) * w.v + mix * aw;
        if (++uphill_free > kStepsBeforeGrowing) step = std::min(step * kStepGrow, max_step), alpha *= kAlphaShrink;
      } else {
        f.v.setZero();
        w.v.setZero();
        step *= kStepShrink;
        alpha = kAlphaStart;
        uphill_free = 0;
      }
      f.v += step * af;
      w.v += step * aw;
      const double fastest = std::sqrt(std::max(f.v.colwise().squaredNorm().maxCoeff(),
                                                w.v.colwise().squaredNorm().maxCoeff()));
      if (fastest * step > kMaxMoveOverSpacing * dx) step = kMaxMoveOverSpacing * dx / fastest;
      f.x += step * f.v;
      w.x += step * w.v;
    }
    report.converged = report.residual <= tolerance;
  }
  report.mass_ratio = f.m.sum() / mass_before;
  report.volume_ratio = wall_surface(w.x, sim.mesh()).volume_m3 / volume_before;
  sim.start_at_rest();
  try {
    sim.check_containment();
  } catch (const NumericalFailure& e) {
    throw NumericalFailure(std::string("the relaxation at rest (settle) pushed a particle out: ") + e.what());
  }
  return report;
}

}  // namespace cellsim
