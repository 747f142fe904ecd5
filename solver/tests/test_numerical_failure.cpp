// A run that blows up stops with a message saying where and why (model.md §7, the state checks of
// every step), and leaves only a file marked partial, never one that looks complete.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "cli_helpers.hpp"
#include "core/errors.hpp"
#include "engine/simulation.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"
#include "small_cell.hpp"

using namespace cellsim;

namespace {

Simulation small_simulation() {
  Params p = cellsim::testing::small_cell_case();
  return Simulation(p, build_tissue(p));
}

// The message of the NumericalFailure the next step throws ("" if none).
std::string failure_of_next_step(Simulation& sim) {
  try {
    sim.step();
  } catch (const NumericalFailure& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(NumericalFailure, ANonFiniteVelocityNamesTheParticleAndStep) {
  Simulation sim = small_simulation();
  sim.step();
  sim.mutable_state().fluid.v.col(7) << 0.0, std::nan(""), 0.0;
  const std::string message = failure_of_next_step(sim);
  EXPECT_NE(message.find("step 2 "), std::string::npos) << message;  // the step that made it
  EXPECT_NE(message.find("fluid particle 7 has a non-finite"), std::string::npos) << message;
}

TEST(NumericalFailure, AnInfiniteWallPositionIsCaught) {
  Simulation sim = small_simulation();
  sim.mutable_state().wall.x(2, 11) = INFINITY;
  const std::string message = failure_of_next_step(sim);
  EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
}

TEST(NumericalFailure, ANegativeDensityNamesTheParticle) {
  Simulation sim = small_simulation();
  sim.mutable_state().fluid.rho[5] = -1.0;
  const std::string message = failure_of_next_step(sim);
  EXPECT_NE(message.find("fluid particle 5 has density"), std::string::npos) << message;
}

TEST(NumericalFailure, TheSoundSpeedLimitNamesTheFastestParticle) {
  // 0.25 h / (c0 + |v|max) falls below dt = 0.5 ns once a particle moves at ~3.3 km/s (h = 1.8 um).
  Simulation sim = small_simulation();
  sim.mutable_state().fluid.v.col(9) << 0.0, 5e3, 0.0;
  const std::string message = failure_of_next_step(sim);
  EXPECT_NE(message.find("sound-speed CFL limit"), std::string::npos) << message;
  EXPECT_NE(message.find("at fluid particle 9"), std::string::npos) << message;
  EXPECT_NE(message.find("reduce time.dt_ns"), std::string::npos) << message;
}

TEST(NumericalFailure, TheViscousLimitStopsAToViscousFluid) {
  // 0.125 h^2 rho0 / mu < 0.5 ns for mu above ~0.8 Pa s at h = 1.8 um.
  Params p = cellsim::testing::small_cell_case({{"fluid", {{"viscosity_Pa_s", 50.0}}}});
  Simulation sim(p, build_tissue(p));
  const std::string message = failure_of_next_step(sim);
  EXPECT_NE(message.find("viscous limit"), std::string::npos) << message;
}

TEST(NumericalFailure, TheAccelerationLimitNamesTheParticle) {
  // 0.25 sqrt(h / |a|max) < 0.5 ns for |a| above ~4e14 m/s^2: a particle pressed into a wall particle.
  Simulation sim = small_simulation();
  State& s = sim.mutable_state();
  s.fluid.x.col(4) = s.wall.x.col(0) * (1 - 1e-3);  // 20 nm inside the wall particle: LJ ~ r^-9
  sim.refresh_rates();
  const std::string message = failure_of_next_step(sim);
  EXPECT_NE(message.find("acceleration limit"), std::string::npos) << message;
  EXPECT_NE(message.find("at fluid particle 4"), std::string::npos) << message;
}

TEST(NumericalFailure, AWallTurnedInsideOutStopsTheRun) {
  Simulation sim = small_simulation();
  sim.mutable_state().wall.x.row(0) *= -1.0;  // mirrored: every triangle now faces inward, V < 0
  const std::string message = failure_of_next_step(sim);
  EXPECT_NE(message.find("encloses a volume of -"), std::string::npos) << message;
}

TEST(NumericalFailure, AHealthyStateRunsOn) {
  Simulation sim = small_simulation();
  for (int n = 0; n < 20; ++n) EXPECT_EQ(failure_of_next_step(sim), "");
}

namespace {

// Runs the baseline case at 50 times the paper's turgor, with `extra` options: the run must exit with
// code 3, name `what` and the particle outside the wall, and leave only OUT.h5.partial.
void expect_blowup_leaves_only_a_partial_file(const char* scratch, const cellsim::testing::Args& extra, const char* what) {
  cellsim::testing::ScratchDir dir(scratch);
  cellsim::testing::Args args = {"run", std::string(CELLSIM_SOURCE_DIR) + "/solver/examples/apple-baseline.json", "-o",
                                 dir.file("out.h5"), "--quiet", "--set", "cell.turgor_kPa=5000", "--set", "compression.steps=0"};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = cellsim::testing::run_cli(args, dir);
  EXPECT_EQ(r.exit_code, kExitNumericalFailure) << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("outside the cell wall"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.h5")));
  EXPECT_TRUE(std::filesystem::exists(dir.file("out.h5.partial")));
}

}  // namespace

TEST(NumericalFailure, TheCliExitsWithCodeThreeAndLeavesOnlyAPartialFile) {
  // 5 MPa pushes the fluid through the wall within a microsecond (started from the cell as built,
  // so that the time stepping is what fails).
  expect_blowup_leaves_only_a_partial_file("blowup", {"--set", "drying.steps=2000", "--set", "settle.max_iterations=0"},
                                           "numerical failure: step ");
}

TEST(NumericalFailure, ARelaxationAtRestThatPushesFluidOutStopsTheRunBeforeAnyStep) {
  // No wall holds 5 MPa of turgor at rest: the relaxation itself finds the fluid outside.
  expect_blowup_leaves_only_a_partial_file("settle-leak", {}, "relaxation at rest (settle)");
}
