// The start at rest (settle.hpp): the relaxed fresh cell is in balance at its turgor (the wall
// carries the fluid pressure, the fluid's residual push is small), and dynamics started from it stay
// calm, where the cell as built launches its boundary particles.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine/settle.hpp"
#include "engine/simulation.hpp"
#include "engine/sph_fluid.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"

using namespace cellsim;

namespace {

// The reduced cell of config/ci.yaml (seconds, not minutes), with the 3x LJ repulsion it needs.
Params small_case() {
  return validate_case(nlohmann::json::parse(R"({"cell": {"n_wall": 642, "n_fluid": 700},
                                                 "coupling": {"repulsion_f0_N_m": 1.5e-11}})"));
}

// The fastest fluid particle over `steps` steps.
double fastest_over(Simulation& sim, int steps) {
  double fastest = 0;
  for (int n = 0; n < steps; ++n) {
    sim.step();
    fastest = std::max(fastest, std::sqrt(sim.state().fluid.v.colwise().squaredNorm().maxCoeff()));
  }
  return fastest;
}

}  // namespace

TEST(Settle, RelaxesTheFreshCellToRestAtItsTurgorWithTheWallCarryingTheFluidPressure) {
  Params p = small_case();
  const Tissue cell = build_tissue(p);  // fills in the derived parameters (h0, r0)
  Simulation sim(p, cell);
  const SettleReport r = settle(sim, p.settle_max_iterations, p.settle_tolerance);
  EXPECT_TRUE(r.converged) << r.iterations << " iterations, residual " << r.residual;
  EXPECT_LE(r.residual, p.settle_tolerance);
  const State& s = sim.state();
  EXPECT_EQ(s.time_s, 0.0);
  EXPECT_EQ(s.step, 0);
  EXPECT_TRUE(s.fluid.v.isZero(0.0));
  EXPECT_TRUE(s.wall.v.isZero(0.0));
  EXPECT_TRUE((s.fluid.rho.array() == p.fluid_density_kg_m3).all());  // every particle at P = P_T0
  EXPECT_NEAR(dynamic_cast<const SphFluid&>(sim.fluid()).pressure_Pa().mean(), 200e3, 1e-6);
  EXPECT_NEAR(s.wall_pressure_Pa / 200e3, 1.0, 0.01);                 // the closure's balance
  EXPECT_DOUBLE_EQ(s.initial_fluid_mass_kg, s.fluid.m.sum());         // M_f0 is the settled mass
  EXPECT_DOUBLE_EQ(s.smoothing_length_m, *p.h0_m);                    // D0 of Eq 6 taken at rest
}

TEST(Settle, DynamicsStartedFromRestStayCalmWhereTheCellAsBuiltShocks) {
  Params p = small_case();
  const Tissue cell = build_tissue(p);
  Simulation settled(p, cell);
  settle(settled, p.settle_max_iterations, p.settle_tolerance);
  Simulation as_built(p, cell);
  settle(as_built, 0, p.settle_tolerance);  // zero iterations: only the clock restarts
  const double calm = fastest_over(settled, 2000), shocked = fastest_over(as_built, 2000);
  // The default cell stays under 0.1 m/s (tests/test_drying_physics.py); this reduced one carries
  // ~3x the load per boundary particle (0.15 m/s measured) and its cut lattice launches 0.9 m/s.
  EXPECT_LT(calm, 0.2) << "m/s over the first 2 us";
  EXPECT_GT(shocked, 4 * calm) << "the cut lattice should launch particles: " << shocked << " m/s";
  std::printf("fastest fluid particle over 2 us: %.3f m/s at rest, %.3f m/s as built\n", calm, shocked);
}
