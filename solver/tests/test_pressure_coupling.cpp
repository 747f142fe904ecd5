// The pressure coupling (pressure_coupling.hpp, docs/model.md §4): equal and opposite pair forces; the
// wall carries P x its area for a uniform pressure (the discrete ∮ W n dS against the divergence
// theorem); the force and the density term are conjugate (the pair's power is what its density term
// gives the internal energy); a wall moving into the fluid raises its density; at a fold, the far sheet
// of wall does not push fluid through the near one; the backstop pushes back only closer than its range;
// and a pressurised cell at rest stays at rest, holds its pressure and keeps every particle inside.
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
  Eigen::Matrix3Xd on_fluid, on_wall, backstop_on_wall;
  Eigen::VectorXd drho_dt;
  double backstop_power_W = 0;
};

// The coupling alone on given particles: forces with the given fluid pressures, density rates with the
// given velocities.
Forces coupling_forces(const FluidParticles& fluid, const WallParticles& wall, const Eigen::Matrix3Xd& vertex_normal,
                       double h, const Eigen::VectorXd& pressure, const PressureCouplingLaw& law = {}) {
  NeighbourLists lists(0.0);
  lists.update(fluid.x, wall.x, 2 * h, 2 * h);
  const auto n = fluid.size();
  Forces out{Eigen::Matrix3Xd::Zero(3, n), {}, {}, Eigen::VectorXd::Zero(n)};
  PressureCouplingScratch scratch;
  pressure_coupling_weights(fluid.x, wall.x, vertex_normal, lists.fluid_wall(), CubicSplineKernel(h), law, 1, scratch);
  add_pressure_coupling_density_rates(fluid, wall, lists.fluid_wall(), scratch, 1, out.drho_dt);
  out.backstop_power_W = pressure_coupling_forces(fluid, pressure, wall, lists.fluid_wall(), 1, scratch, out.on_fluid,
                                                  out.on_wall, out.backstop_on_wall);
  return out;
}

// A built cell's particles at rest (fluid at rho0).
struct CellParticles {
  FluidParticles fluid;
  WallParticles wall;
  Eigen::Matrix3Xd vertex_normal;
};
CellParticles particles_of(const Cell& cell) {
  const auto n = cell.fluid_x.cols();
  return {{cell.fluid_x, Eigen::Matrix3Xd::Zero(3, n), Eigen::VectorXd::Constant(n, cell.fluid_mass_kg),
           Eigen::VectorXd::Constant(n, 1000.0)},
          {cell.wall_x, Eigen::Matrix3Xd::Zero(3, cell.wall_x.cols()), cell.wall_mass_kg},
          wall_surface(cell.wall_x, cell.mesh).vertex_normal};
}

// A fluid half-space z > 0 on lattice spacing dx (first layer at dx/2), and a flat wall sheet at
// z = wall_z with outward normal (0, 0, outward_z) on spacing a: a flat vertex owns a x a, its six
// triangles' area normals sum to 6 a^2.
struct Slab {
  FluidParticles fluid;
  WallParticles wall;
  Eigen::Matrix3Xd vertex_normal;
};
constexpr double kDx = 1e-6, kH = 1.5 * kDx, kA = 0.5 * kDx;
constexpr int kSide = 16, kDepth = 5, kWallSide = 24;

Eigen::Matrix3Xd sheet_normals(double outward_z) {
  Eigen::Matrix3Xd normals(3, kWallSide * kWallSide);
  normals.row(0).setZero();
  normals.row(1).setZero();
  normals.row(2).setConstant(6 * kA * kA * outward_z);
  return normals;
}

Slab slab(const std::vector<std::pair<double, double>>& sheets) {  // (z, outward_z) of each sheet
  Slab s;
  const int n = kSide * kSide * kDepth;
  s.fluid.x.resize(3, n);
  int q = 0;
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j)
      for (int k = 0; k < kDepth; ++k)
        s.fluid.x.col(q++) << (i - kSide / 2 + 0.5) * kDx, (j - kSide / 2 + 0.5) * kDx, (k + 0.5) * kDx;
  s.fluid.v = Eigen::Matrix3Xd::Zero(3, n);
  s.fluid.m = Eigen::VectorXd::Constant(n, 1000.0 * kDx * kDx * kDx);
  s.fluid.rho = Eigen::VectorXd::Constant(n, 1000.0);
  const int per_sheet = kWallSide * kWallSide;
  s.wall.x.resize(3, per_sheet * static_cast<int>(sheets.size()));
  s.vertex_normal.resize(3, s.wall.x.cols());
  q = 0;
  for (std::size_t b = 0; b < sheets.size(); ++b) {
    s.vertex_normal.middleCols(static_cast<Eigen::Index>(b) * per_sheet, per_sheet) = sheet_normals(sheets[b].second);
    for (int i = 0; i < kWallSide; ++i)
      for (int j = 0; j < kWallSide; ++j) s.wall.x.col(q++) << (i - kWallSide / 2) * kA, (j - kWallSide / 2) * kA, sheets[b].first;
  }
  s.wall.v = Eigen::Matrix3Xd::Zero(3, s.wall.x.cols());
  s.wall.mass_kg = 1e-15;
  return s;
}

}  // namespace

TEST(PressureCoupling, PairForcesAreEqualAndOpposite) {
  Params p = pressure_cell();
  const CellParticles c = particles_of(build_cell(p));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pressure(-5e4, 4e5);
  Eigen::VectorXd P(c.fluid.size());
  for (auto& x : P) x = pressure(rng);  // unequal, some in tension
  // A backstop reaching past the first fluid layer, so that it acts too.
  const PressureCouplingLaw law{0.8 * *p.h0_m, 2e7};
  const Forces f = coupling_forces(c.fluid, c.wall, c.vertex_normal, *p.h0_m, P, law);
  ASSERT_GT(f.backstop_on_wall.norm(), 0);
  const double scale = f.on_wall.colwise().norm().sum();
  ASSERT_GT(scale, 0);
  EXPECT_LT((f.on_fluid.rowwise().sum() + f.on_wall.rowwise().sum()).norm(), 1e-13 * scale);
}

TEST(PressureCoupling, UniformPressureLoadsAFlatWallWithPressureTimesArea) {
  // The continuum statement behind the coupling: a fluid half-space whose particle volumes reach a flat
  // wall loads each wall patch with P x its area (2 P sum_i V_i W_ik approximating P), in compression
  // and in tension alike. Resolved here (h = 1.5 dx).
  Slab s = slab({{0.0, -1.0}});
  const int centre = (kWallSide / 2) * kWallSide + kWallSide / 2;
  for (const double P : {2e5, -5e4}) {
    const Forces f = coupling_forces(s.fluid, s.wall, s.vertex_normal, kH, Eigen::VectorXd::Constant(s.fluid.size(), P));
    EXPECT_NEAR(f.on_wall(2, centre) / (-P * kA * kA), 1.0, 0.03) << P;  // along -z (outward) when P > 0
    EXPECT_GT(f.on_fluid.row(2).sum() * P, 0) << P;                     // the reaction on the fluid
    EXPECT_EQ(f.drho_dt.norm(), 0.0);                                   // nothing moves: no density change
  }
}

TEST(PressureCoupling, ForceAndDensityTermAreConjugate) {
  // For any velocities, the pairs' power sum F . v equals minus what their density terms give the
  // internal energy, sum_i m_i P_i / rho_i^2 d(rho_i)/dt: the coupling neither makes nor destroys energy.
  Params p = pressure_cell();
  CellParticles c = particles_of(build_cell(p));
  std::mt19937 rng(11);
  std::normal_distribution<double> speed(0.0, 1.0), pressure(2e5, 1e5);
  for (auto& v : c.fluid.v.reshaped()) v = speed(rng);
  for (auto& v : c.wall.v.reshaped()) v = speed(rng);
  Eigen::VectorXd P(c.fluid.size());
  for (auto& x : P) x = pressure(rng);
  const Forces f = coupling_forces(c.fluid, c.wall, c.vertex_normal, *p.h0_m, P);
  const double power = f.on_fluid.cwiseProduct(c.fluid.v).sum() + f.on_wall.cwiseProduct(c.wall.v).sum();
  const double internal = (c.fluid.m.array() * P.array() / c.fluid.rho.array().square() * f.drho_dt.array()).sum();
  ASSERT_GT(std::abs(power), 0);
  EXPECT_NEAR(power + internal, 0.0, 1e-12 * std::abs(power));
}

TEST(PressureCoupling, AWallMovingInwardRaisesTheDensityNextToIt) {
  Params p = pressure_cell();
  CellParticles c = particles_of(build_cell(p));
  const Eigen::VectorXd uniform = Eigen::VectorXd::Constant(c.fluid.size(), 2e5);
  c.wall.v = -c.wall.x.colwise().normalized();  // every wall particle moves toward the centre
  const Forces inward = coupling_forces(c.fluid, c.wall, c.vertex_normal, *p.h0_m, uniform);
  EXPECT_GT(inward.drho_dt.maxCoeff(), 0);
  EXPECT_GE(inward.drho_dt.minCoeff(), 0);
  c.wall.v = -c.wall.v;
  const Forces outward = coupling_forces(c.fluid, c.wall, c.vertex_normal, *p.h0_m, uniform);
  EXPECT_LT(outward.drho_dt.minCoeff(), 0);
}

TEST(PressureCoupling, TheFarSheetOfAFoldDoesNotPushFluidThroughTheNearOne) {
  // An inward fold: the near sheet A at z = 0 faces the fluid above it (outward normal -z); the far sheet
  // B, 0.8 h below, is another part of the same wall, its outside facing A's (outward normal +z). The
  // fluid sees B from outside: B must add nothing, neither force nor density rate, even when it moves.
  const Slab near = slab({{0.0, -1.0}});
  Slab folded = slab({{0.0, -1.0}, {-0.8 * kH, +1.0}});
  folded.wall.v.rightCols(kWallSide * kWallSide).row(2).setConstant(-3.0);  // B moves away
  const Eigen::VectorXd P = Eigen::VectorXd::Constant(near.fluid.size(), 2e5);
  const Forces a = coupling_forces(near.fluid, near.wall, near.vertex_normal, kH, P);
  const Forces ab = coupling_forces(folded.fluid, folded.wall, folded.vertex_normal, kH, P);
  EXPECT_EQ((ab.on_fluid - a.on_fluid).norm(), 0.0);
  EXPECT_EQ((ab.drho_dt - a.drho_dt).norm(), 0.0);
  EXPECT_EQ(ab.on_wall.rightCols(kWallSide * kWallSide).norm(), 0.0);
  // Without the one-sided weight B would push the first fluid layer (within B's reach) down through A
  // (-z): it is pushed up, by A alone.
  for (Eigen::Index i = 0; i < folded.fluid.size(); ++i)
    if (folded.fluid.x(2, i) < kDx) EXPECT_GT(ab.on_fluid(2, i), 0.0) << i;
}

TEST(PressureCoupling, TheBackstopPushesBackOnlyWithinItsRange) {
  // One fluid particle above the sheet at depth d: below the range d_b nothing; closer, a push inward
  // (+z) that grows as d falls, and also just past the wall's plane; the wall gets the reaction.
  const PressureCouplingLaw law{0.25 * kDx, 2e7};
  const auto backstop_at = [&](double depth) {
    Slab s = slab({{0.0, -1.0}});
    FluidParticles one{Eigen::Vector3d(0.1 * kA, 0.2 * kA, depth), Eigen::Matrix3Xd::Zero(3, 1),
                       Eigen::VectorXd::Constant(1, 1e-15), Eigen::VectorXd::Constant(1, 1000.0)};
    const Forces f = coupling_forces(one, s.wall, s.vertex_normal, kH, Eigen::VectorXd::Zero(1), law);
    EXPECT_NEAR(f.backstop_on_wall.rowwise().sum()(2), -f.on_fluid(2, 0), 1e-12 * std::abs(f.on_fluid(2, 0)));
    return f.on_fluid(2, 0);  // P = 0: the force is the backstop's alone
  };
  EXPECT_EQ(backstop_at(0.3 * kDx), 0.0);
  const double far = backstop_at(0.2 * kDx), near = backstop_at(0.05 * kDx), past = backstop_at(-0.05 * kDx);
  EXPECT_GT(far, 0.0);
  EXPECT_GT(near, far);
  EXPECT_GT(past, near);
  EXPECT_EQ(backstop_at(-0.3 * kDx), 0.0);  // farther out than d_b: another sheet's fluid, or gone
}

// The weights go four pairs of a row at a time and the rest of the row one by one: every pair, in
// either, gets what the laws give it alone (w(d) W(r) and p_b(d) W(r)), to round-off (the compiler may
// fuse a multiply and an add in one and not the other), and exact zeros beyond the support; in the
// skin, the fade and the backstop's range.
TEST(PressureCoupling, FourPairsAtOnceWeighEachAsTheLawsDo) {
  Params p = pressure_cell();
  const CellParticles c = particles_of(build_cell(p));
  const double h = *p.h0_m;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.3 * h, 0.3 * h);
  // The cell's fluid jittered, and a particle just outside each of 40 wall particles, in their fade.
  const Eigen::Index n = c.fluid.size(), outside = 40;
  Eigen::Matrix3Xd fluid_x(3, n + outside);
  for (Eigen::Index i = 0; i < n; ++i) fluid_x.col(i) = c.fluid.x.col(i) + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
  for (Eigen::Index k = 0; k < outside; ++k)
    fluid_x.col(n + k) = c.wall.x.col(k * 7) + 0.05 * h * c.vertex_normal.col(k * 7).normalized();
  const PressureCouplingLaw law{0.8 * h, 2e7};
  NeighbourLists lists(0.3 * h);  // a skin: some listed pairs lie beyond the support
  lists.update(fluid_x, c.wall.x, 2 * h, 2 * h);
  const PairList& pairs = lists.fluid_wall();
  const CubicSplineKernel kernel(h);
  PressureCouplingScratch scratch;
  pressure_coupling_weights(fluid_x, c.wall.x, c.vertex_normal, pairs, kernel, law, 1, scratch);
  const double fade = kFadeOverH * h;
  int in_fade = 0, in_backstop = 0, beyond = 0, lanes = 0, alone = 0;
  for (int i = 0; i < pairs.rows(); ++i) {
    const int first = pairs.offset[i], count = pairs.offset[i + 1] - first;
    for (int q = first; q < first + count; ++q) {
      const int k = pairs.index[q];
      const Eigen::Vector3d to_wall = c.wall.x.col(k) - fluid_x.col(i), normal = scratch.unit_normal.col(k);
      const double r2 = to_wall[0] * to_wall[0] + to_wall[1] * to_wall[1] + to_wall[2] * to_wall[2];
      const double depth = to_wall[0] * normal[0] + to_wall[1] * normal[1] + to_wall[2] * normal[2];
      const double W = kernel.W(std::sqrt(r2));
      ASSERT_NEAR(scratch.weight[q], one_sided_weight(depth, fade) * W, 1e-14 * kernel.W(0.0)) << "pair " << q;
      ASSERT_NEAR(scratch.backstop[q], backstop_pressure_Pa(depth, law) * W, 1e-14 * law.backstop_pressure_Pa * kernel.W(0.0))
          << "pair " << q;
      if (W == 0) ASSERT_EQ(scratch.weight[q], 0.0) << "pair " << q;
      in_fade += depth < 0 && depth > -fade && W > 0;
      in_backstop += scratch.backstop[q] > 0;
      beyond += W == 0;
      (q - first < count / 4 * 4 ? lanes : alone) += 1;
    }
  }
  EXPECT_GT(in_fade, 0);
  EXPECT_GT(in_backstop, 0);
  EXPECT_GT(beyond, 0);
  EXPECT_GT(lanes, 0);
  EXPECT_GT(alone, 0);
  EXPECT_TRUE(scratch.any_backstop);
}

TEST(PressureCoupling, APressurisedCellAtRestHoldsItsPressure) {
  // No mass transfer, fresh: after the relaxation at rest, 4000 steps (2 us) keep the turgor, the
  // volume, every particle inside the wall, and the fluid nearly still. The fluid's jitter (~0.03 m/s
  // rms) lets its density relax slowly at a fixed volume (docs/model-closures.md): on this cell of 120
  // particles the pressure falls by 2.4 % in these 2 us, so the turgor is held to 3 %.
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
  EXPECT_NEAR(end.mean_pressure_Pa / p.turgor_Pa, 1.0, 0.03);
  EXPECT_NEAR(end.wall_pressure_Pa / end.mean_pressure_Pa, 1.0, 0.05);
  EXPECT_NEAR(end.volume_m3 / start.volume_m3, 1.0, 0.005);
  EXPECT_LT(end.max_fluid_speed_m_s, 0.2);
}
