// The wall-pressure closure (pressure_closure.hpp, docs/model-closures.md): its factor, its clamp,
// and that it acts during drying only.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/simulation.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"
#include "physics/pressure_closure.hpp"
#include "small_cell.hpp"

using namespace cellsim;

TEST(PressureClosure, FactorShrinksMassesWhenTheWallCarriesMore) {
  const double dt = 1e-9, tau = 2e-6;
  EXPECT_NEAR(pressure_closure_factor(2.2e5, 2e5, dt, tau), std::pow(1.1, -dt / (2 * tau)), 1e-15);
  EXPECT_LT(pressure_closure_factor(2.2e5, 2e5, dt, tau), 1.0);  // wall carries more: volumes shrink
  EXPECT_GT(pressure_closure_factor(1.8e5, 2e5, dt, tau), 1.0);
  EXPECT_EQ(pressure_closure_factor(2e5, 2e5, dt, tau), 1.0);
}

TEST(PressureClosure, RatioIsClampedAndNoTurgorMeansNoChange) {
  const double dt = 1e-9, tau = 2e-6;
  EXPECT_EQ(pressure_closure_factor(1e7, 2e5, dt, tau), std::pow(2.0, -dt / (2 * tau)));  // clamped at 2
  EXPECT_EQ(pressure_closure_factor(1e3, 2e5, dt, tau), std::pow(0.5, -dt / (2 * tau)));  // clamped at 1/2
  EXPECT_EQ(pressure_closure_factor(2e5, -5e4, dt, tau), 1.0);  // mean pressure not positive
  EXPECT_EQ(pressure_closure_factor(0.0, 2e5, dt, tau), 1.0);   // no push on the wall
  EXPECT_EQ(pressure_closure_factor(2.2e5, 2e5, dt, 0.0), 1.0); // tau = 0 switches it off
}

TEST(PressureClosure, ActsInDryingAndIsOffInCompression) {
  // With L_p = 0 in both stages, Eq 11 moves no mass, so any change of a fluid mass is the closure's.
  Params p = cellsim::testing::small_cell_case();
  p.drying_Lp_m_per_s_Pa = p.compression_Lp_m_per_s_Pa = 0;
  Simulation sim(p, build_tissue(p));
  Eigen::VectorXd before = sim.state().fluid.m;
  for (int n = 0; n < 5; ++n) sim.step();
  EXPECT_GT((sim.state().fluid.m - before).cwiseAbs().maxCoeff(), 0.0) << "the closure should act in drying";
  sim.start_compression();
  before = sim.state().fluid.m;
  for (int n = 0; n < 5; ++n) sim.step();
  EXPECT_EQ((sim.state().fluid.m - before).cwiseAbs().maxCoeff(), 0.0) << "the closure must be off in compression";
}
