// The pressure coupling (pressure_coupling.hpp, model.md §4): equal and opposite pair forces; the
// wall carries P x its area for a uniform pressure (the discrete ∮ W n dS against the divergence
// theorem); a wall moving into the fluid raises its density; and a pressurised cell at rest stays at
// rest, holds its pressure and keeps every particle inside.
#include <gtest/gtest.h>

#include <random>

#include "engine/settle.hpp"
#include "engine/simulation.hpp"
#include "geometry/cell.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"
#include "physics/pressure_coupling.hpp"
#include "small_cell.hpp"

using namespace cellsim;

namespace {

Params pressure_cell(const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json doc = {{"coupling", {{"model", "pressure"}}}};
  doc.merge_patch(extra);
  return cellsim::testing::small_cell_case(doc);
}

struct Forces {
  Eigen::Matrix3Xd on_fluid, on_wall;
  Eigen::VectorXd drho_dt;
};

// The coupling alone on a cell's particles, with the given fluid pressures and velocities.
Forces coupling_forces(const Cell& cell, double h, const Eigen::VectorXd& pressure, const Eigen::Matrix3Xd& fluid_v,
                       const Eigen::Matrix3Xd& wall_v) {
  const auto n = cell.fluid_x.cols();
  NeighbourLists lists(0.0);
  lists.update(cell.fluid_x, cell.wall_x, 2 * h, 2 * h);
  const WallSurface surface = wall_surface(cell.wall_x, cell.mesh);
  Forces out{Eigen::Matrix3Xd::Zero(3, n), {}, Eigen::VectorXd::Zero(n)};
  const FluidParticles fluid{cell.fluid_x, fluid_v, Eigen::VectorXd::Constant(n, cell.fluid_mass_kg),
                             Eigen::VectorXd::Constant(n, 1000.0)};
  const WallParticles wall{cell.wall_x, wall_v, cell.wall_mass_kg};
  PressureCouplingScratch scratch;
  pressure_coupling_forces(fluid, pressure, wall, surface.vertex_normal, lists.fluid_wall(), CubicSplineKernel(h), 1,
                           scratch, out.on_fluid, out.drho_dt, out.on_wall);
  return out;
}

}  // namespace

TEST(PressureCoupling, PairForcesAreEqualAndOpposite) {
  Params p = pressure_cell();
  const Cell cell = build_cell(p);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pressure(-5e4, 4e5);
  Eigen::VectorXd P(cell.fluid_x.cols());
  for (auto& x : P) x = pressure(rng);  // unequal, some in tension
  const auto zero_f = Eigen::Matrix3Xd::Zero(3, cell.fluid_x.cols());
  const auto zero_w = Eigen::Matrix3Xd::Zero(3, cell.wall_x.cols());
  const Forces f = coupling_forces(cell, *p.h0_m, P, zero_f, zero_w);
  const double scale = f.on_wall.colwise().norm().sum();
  ASSERT_GT(scale, 0);
  EXPECT_LT((f.on_fluid.rowwise().sum() + f.on_wall.rowwise().sum()).norm(), 1e-13 * scale);
}

TEST(PressureCoupling, UniformPressureLoadsAFlatWallWithPressureTimesArea) {
  // The continuum statement behind the closure: a fluid half-space whose particle volumes reach a
  // flat wall (first layer at dx/2) loads each wall patch with P x its area, the discrete sum
  // 2 P sum_i V_i W_ik approximating P (2 x the half-space integral of W). Resolved here (h = 1.5 dx).
  const double dx = 1e-6, h = 1.5 * dx, a = 0.5 * dx, P = 2e5;
  const int n_side = 16, n_depth = 5, n_wall_side = 24;
  Eigen::Matrix3Xd fluid_x(3, n_side * n_side * n_depth), wall_x(3, n_wall_side * n_wall_side);
  int q = 0;
  for (int i = 0; i < n_side; ++i)
    for (int j = 0; j < n_side; ++j)
      for (int k = 0; k < n_depth; ++k) fluid_x.col(q++) << (i - n_side / 2 + 0.5) * dx, (j - n_side / 2 + 0.5) * dx, (k + 0.5) * dx;
  q = 0;
  for (int i = 0; i < n_wall_side; ++i)
    for (int j = 0; j < n_wall_side; ++j) wall_x.col(q++) << (i - n_wall_side / 2) * a, (j - n_wall_side / 2) * a, 0.0;
  // Outward (-z) area normals: a flat vertex owns a x a, its six triangles' normals sum to 6 a^2.
  const Eigen::Matrix3Xd vertex_normal = Eigen::Vector3d(0, 0, -6 * a * a).replicate(1, wall_x.cols());
  NeighbourLists lists(0.0);
  lists.update(fluid_x, wall_x, 2 * h, 2 * h);
  const auto n = fluid_x.cols();
  const FluidParticles fluid{fluid_x, Eigen::Matrix3Xd::Zero(3, n), Eigen::VectorXd::Constant(n, 1000.0 * dx * dx * dx),
                             Eigen::VectorXd::Constant(n, 1000.0)};
  const WallParticles wall{wall_x, Eigen::Matrix3Xd::Zero(3, wall_x.cols()), 1e-15};
  Eigen::Matrix3Xd on_fluid = Eigen::Matrix3Xd::Zero(3, n), on_wall;
  Eigen::VectorXd drho = Eigen::VectorXd::Zero(n);
  PressureCouplingScratch scratch;
  pressure_coupling_forces(fluid, Eigen::VectorXd::Constant(n, P), wall, vertex_normal, lists.fluid_wall(),
                           CubicSplineKernel(h), 1, scratch, on_fluid, drho, on_wall);
  const int centre = (n_wall_side / 2) * n_wall_side + n_wall_side / 2;
  EXPECT_NEAR(-on_wall(2, centre) / (P * a * a), 1.0, 0.03);  // pushed out, along -z
  EXPECT_NEAR(scratch.shepard(1, centre), P, 1e-9 * P);    // the Shepard average of a uniform field
  EXPECT_GT(on_fluid.row(2).sum(), 0);                        // the fluid is pushed back in, along +z
  EXPECT_EQ(drho.norm(), 0.0);                                // nothing moves: no density change
}

TEST(PressureCoupling, FluidInTensionIsNotPulledOntoTheWall) {
  Params p = pressure_cell();
  const Cell cell = build_cell(p);
  const Eigen::VectorXd tension = Eigen::VectorXd::Constant(cell.fluid_x.cols(), -1e5);
  const Forces none = coupling_forces(cell, *p.h0_m, tension, Eigen::Matrix3Xd::Zero(3, cell.fluid_x.cols()),
                                      Eigen::Matrix3Xd::Zero(3, cell.wall_x.cols()));
  EXPECT_EQ(none.on_wall.norm(), 0.0);
  EXPECT_EQ(none.on_fluid.norm(), 0.0);
}

TEST(PressureCoupling, AWallMovingInwardRaisesTheDensityNextToIt) {
  Params p = pressure_cell();
  const Cell cell = build_cell(p);
  const auto n = cell.fluid_x.cols();
  const Eigen::VectorXd uniform = Eigen::VectorXd::Constant(n, 2e5);
  Eigen::Matrix3Xd inward = -cell.wall_x;  // every wall particle moves toward the centre
  for (Eigen::Index k = 0; k < inward.cols(); ++k) inward.col(k).normalize();
  const Forces f = coupling_forces(cell, *p.h0_m, uniform, Eigen::Matrix3Xd::Zero(3, n), inward);
  EXPECT_GT(f.drho_dt.maxCoeff(), 0);
  EXPECT_GE(f.drho_dt.minCoeff(), 0);
  const Forces outward = coupling_forces(cell, *p.h0_m, uniform, Eigen::Matrix3Xd::Zero(3, n), -inward);
  EXPECT_LT(outward.drho_dt.minCoeff(), 0);
}

TEST(PressureCoupling, APressurisedCellAtRestHoldsItsPressure) {
  // No mass transfer, fresh: after the relaxation at rest, 4000 steps (2 us) keep the turgor, the
  // volume, every particle inside the wall, and the fluid nearly still.
  Params p = pressure_cell({{"drying", {{"Lp_m_per_s_Pa", 0}, {"pressure_closure_time_us", 0}}}});
  Simulation sim(p, build_tissue(p));
  const SettleReport settled = settle(sim, p.settle_max_iterations, p.settle_tolerance);
  ASSERT_TRUE(settled.converged);
  const Record start = sim.record();
  for (int n = 0; n < 4000; ++n) {
    sim.step();
    if (n % 500 == 0) ASSERT_NO_THROW(sim.check_containment()) << "step " << n;
  }
  const Record end = sim.record();
  EXPECT_NEAR(end.mean_pressure_Pa / p.turgor_Pa, 1.0, 0.02);
  EXPECT_NEAR(end.wall_pressure_Pa / end.mean_pressure_Pa, 1.0, 0.05);
  EXPECT_NEAR(end.volume_m3 / start.volume_m3, 1.0, 0.005);
  EXPECT_LT(end.max_fluid_speed_m_s, 0.2);
}
