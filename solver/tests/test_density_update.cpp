// When the leapfrog advances the fluid's density (density_update.hpp, docs/model.md §7): auto follows
// the coupling; with drift a step's density is its start density plus dt times the continuity rate at
// the drifted positions and the half-step velocities; with kick, half the old rate and half the new.
#include <gtest/gtest.h>

#include <random>

#include "engine/density_update.hpp"
#include "engine/simulation.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"
#include "physics/fluid_pairs.hpp"
#include "physics/pressure_coupling.hpp"
#include "small_cell.hpp"

using namespace cellsim;

namespace {

// The small cell with the pressure coupling, closed (no Eq 11) and without the closure, so that only
// continuity moves the density; particles given random velocities, rates taken at them.
Simulation moving_cell(const std::string& density_update) {
  Params p = cellsim::testing::small_cell_case(
      {{"coupling", {{"model", "pressure"}}},
       {"drying", {{"Lp_m_per_s_Pa", 0}, {"pressure_closure_time_us", 0}}},
       {"time", {{"density_update", density_update}}}});
  Simulation sim(p, build_tissue(p));
  State& s = sim.mutable_state();
  std::mt19937 rng(3);
  std::normal_distribution<double> speed(0.0, 0.3);
  for (auto& v : s.fluid.v.reshaped()) v = speed(rng);
  for (auto& v : s.wall.v.reshaped()) v = speed(rng);
  sim.refresh_rates();
  return sim;
}

// The continuity rate (Eq 10 and the pressure coupling's wall term) of fluid f next to wall w, whose
// smoothing length follows the wall's volume (Eq 6), computed here from the public pieces.
Eigen::VectorXd continuity_rate(const Simulation& sim, const FluidParticles& f, const WallParticles& w) {
  const Params& p = sim.params();
  const double h = equivalent_diameter_m(wall_surface(w.x, sim.mesh()).volume_m3) / sim.state().reference_diameter_m *
                   *p.h0_m;
  const CubicSplineKernel kernel(h);
  NeighbourLists lists(0.0);
  lists.update(f.x, w.x, kernel.support(), kernel.support());
  FluidRates rates;
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, sim.eos(), p.viscosity_Pa_s, 1, rates, 0.0, PairTerms::Continuity);
  PressureCouplingScratch scratch;
  pressure_coupling_weights(f.x, w.x, wall_surface(w.x, sim.mesh()).vertex_normal, lists.fluid_wall(), kernel, {}, 1,
                            scratch);
  add_pressure_coupling_density_rates(f, w, lists.fluid_wall(), scratch, 1, rates.drho_dt);
  return rates.drho_dt;
}

// The particles after a step's first half kick and its drift.
std::pair<FluidParticles, WallParticles> half_kicked_and_drifted(const Simulation& sim) {
  const double dt = sim.params().dt_s;
  FluidParticles f = sim.state().fluid;
  WallParticles w = sim.state().wall;
  for (Eigen::Index i = 0; i < f.size(); ++i) f.v.col(i) += 0.5 * dt / f.m[i] * sim.fluid_force().col(i);
  w.v += 0.5 * dt / w.mass_kg * sim.wall_force();
  f.x += dt * f.v;
  w.x += dt * w.v;
  return {f, w};
}

}  // namespace

TEST(DensityUpdate, AutoFollowsTheCoupling) {
  const auto resolved = [](const char* coupling, const char* update) {
    return cellsim::testing::small_cell_case({{"coupling", {{"model", coupling}}}, {"time", {{"density_update", update}}}})
        .density_update;
  };
  EXPECT_EQ(resolved("lennard_jones", "auto"), kDensityKick);
  EXPECT_EQ(resolved("pressure", "auto"), kDensityDrift);
  EXPECT_EQ(resolved("lennard_jones", "drift"), kDensityDrift);
  EXPECT_EQ(resolved("pressure", "kick"), kDensityKick);
}

TEST(DensityUpdate, DriftAdvancesTheDensityByTheRateAtTheHalfStepVelocities) {
  Simulation sim = moving_cell("drift");
  const double dt = sim.params().dt_s;
  const Eigen::VectorXd rho0 = sim.state().fluid.rho;
  const auto [f, w] = half_kicked_and_drifted(sim);
  FluidParticles start_density = f;
  start_density.rho = rho0;
  const Eigen::VectorXd expected = rho0 + dt * continuity_rate(sim, start_density, w);
  sim.step();
  const Eigen::VectorXd change = expected - rho0;
  ASSERT_GT(change.cwiseAbs().maxCoeff(), 1e-6 * rho0.maxCoeff());  // the velocities did move the density
  EXPECT_LT((sim.state().fluid.rho - expected).cwiseAbs().maxCoeff(), 1e-9 * change.cwiseAbs().maxCoeff());
}

TEST(DensityUpdate, KickTakesHalfTheOldRateAndHalfTheNew) {
  Simulation sim = moving_cell("kick");
  const double dt = sim.params().dt_s;
  const FluidParticles before = sim.state().fluid;
  const Eigen::VectorXd old_rate = continuity_rate(sim, before, sim.state().wall);
  const auto [f, w] = half_kicked_and_drifted(sim);
  FluidParticles half = f;
  half.rho = before.rho + 0.5 * dt * old_rate;  // the first half kick's density: the new rate sees it
  const Eigen::VectorXd expected = half.rho + 0.5 * dt * continuity_rate(sim, half, w);
  sim.step();
  const Eigen::VectorXd change = expected - before.rho;
  ASSERT_GT(change.cwiseAbs().maxCoeff(), 1e-6 * before.rho.maxCoeff());
  EXPECT_LT((sim.state().fluid.rho - expected).cwiseAbs().maxCoeff(), 1e-9 * change.cwiseAbs().maxCoeff());
}
