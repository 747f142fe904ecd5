// Threads in every phase (threads.hpp, owned_spans.hpp, block_sums.hpp): the wall loops give the
// same bits for any thread count; the loops with per-thread sums are reproducible for a count and
// agree with one thread to round-off; a whole step is reproducible and agrees to round-off.
#include <gtest/gtest.h>

#include <random>

#include "engine/simulation.hpp"
#include "geometry/cell.hpp"
#include "geometry/neighbours.hpp"
#include "geometry/surface.hpp"
#include "geometry/tissue.hpp"
#include "parallel/threads.hpp"
#include "physics/bending.hpp"
#include "physics/fluid_pairs.hpp"
#include "physics/wall_bonds.hpp"
#include "physics/wall_fluid.hpp"
#include "small_cell.hpp"

using namespace cellsim;

namespace {

// The default wall (2067 particles), every particle moved at random and given a random velocity, so
// that every bond, hinge and triangle carries a different force.
struct ShakenCell {
  Params p = validate_case(nlohmann::json::object());
  Cell cell = build_cell(p);
  WallParticles wall;
  ShakenCell() {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    wall.x = cell.wall_x;
    wall.v = Eigen::Matrix3Xd(3, wall.x.cols());
    wall.mass_kg = cell.wall_mass_kg;
    const double shift = 0.1 * *p.r0_m;
    for (Eigen::Index k = 0; k < wall.x.cols(); ++k) {
      wall.x.col(k) += shift * Eigen::Vector3d(u(rng), u(rng), u(rng));
      wall.v.col(k) = Eigen::Vector3d(u(rng), u(rng), u(rng));
    }
  }
  // Half dried, with heterogeneous bonds and a wall that yields (the shaken bonds pass 0.1 MPa): every
  // branch of the bond loop.
  BondLaw bond_law() const {
    Params q = p;
    q.dryness = 0.5;
    q.yield_stress_Pa = 0.1e6;
    const PropertyFactors factors = draw_property_factors({7, 0.3, 0.2, 0.0, 5e-6}, wall.x, cell.mesh, {}, 1);
    return make_bond_law(q, factors);
  }
};

struct WallLoops {
  Eigen::Matrix3Xd bonds, bending, vertex_normal;
  double volume_m3, tension_times_length;
};

WallLoops wall_loops(const ShakenCell& s, int threads) {
  WallLoops out;
  WallSurface surface;
  surface.update(s.wall.x, s.cell.mesh, threads);
  out.vertex_normal = surface.vertex_normal;
  out.volume_m3 = surface.volume_m3;
  BondScratch scratch;
  out.bonds = Eigen::Matrix3Xd::Zero(3, s.wall.size());
  std::vector<double> plastic_elongation(s.cell.mesh.bonds.size(), 0.0);
  out.tension_times_length = add_bond_forces(s.wall, s.cell.mesh, s.bond_law(), 0.7, threads, plastic_elongation,
                                             out.bonds, scratch)
                                 .tension_times_length;
  out.bending = Eigen::Matrix3Xd::Zero(3, s.wall.size());
  Bending(s.cell.mesh, s.p.bending_stiffness_J).add_forces(s.wall.x, surface.triangles, threads, out.bending);
  return out;
}

}  // namespace

TEST(Threads, WallLoopsGiveTheSameBitsForAnyThreadCount) {
  if (!built_with_openmp()) GTEST_SKIP() << "built without OpenMP: only one thread";
  const ShakenCell s;
  const WallLoops one = wall_loops(s, 1);
  ASSERT_GT(one.bonds.norm(), 0.0);
  ASSERT_GT(one.bending.norm(), 0.0);
  for (int threads : {2, 3, 7}) {
    const WallLoops many = wall_loops(s, threads);
    EXPECT_TRUE(many.bonds == one.bonds) << threads << " threads";
    EXPECT_TRUE(many.bending == one.bending) << threads << " threads";
    EXPECT_TRUE(many.vertex_normal == one.vertex_normal) << threads << " threads";
    // The two sums over the wall add per-thread parts: equal to round-off.
    EXPECT_NEAR(many.volume_m3, one.volume_m3, 1e-13 * one.volume_m3) << threads << " threads";
    EXPECT_NEAR(many.tension_times_length, one.tension_times_length, 1e-12 * std::abs(one.tension_times_length));
  }
}

TEST(Threads, WallFluidSumsAreReproducibleAndAgreeWithOneThread) {
  if (!built_with_openmp()) GTEST_SKIP() << "built without OpenMP: only one thread";
  const ShakenCell s;
  const LennardJones lj{*s.p.r0_m, 2.0 * *s.p.r0_m, s.p.repulsion_f0_N_m, s.p.attraction_f0_N_m};
  NeighbourLists lists(0.15 * *s.p.h0_m);
  lists.update(s.cell.fluid_x, s.wall.x, 2.0 * *s.p.h0_m, lj.cutoff_m);
  ASSERT_GT(lists.fluid_wall().pairs, 1000u);
  const auto forces = [&](int threads) {
    Eigen::Matrix3Xd on_fluid = Eigen::Matrix3Xd::Zero(3, s.cell.fluid_x.cols()), on_wall;
    WallFluidScratch scratch;
    wall_fluid_forces(s.cell.fluid_x, s.wall.x, lists.fluid_wall(), lj, threads, on_fluid, on_wall, scratch);
    return std::make_pair(on_fluid, on_wall);
  };
  const auto one = forces(1), two = forces(2), two_again = forces(2);
  EXPECT_TRUE(two.first == two_again.first && two.second == two_again.second);  // bit for bit
  EXPECT_TRUE(two.first == one.first);  // each fluid row is one thread's
  const double scale = one.second.colwise().norm().maxCoeff();
  ASSERT_GT(scale, 0.0);
  EXPECT_LT((two.second - one.second).cwiseAbs().maxCoeff(), 1e-12 * scale);
  // Newton's third law holds in the per-thread sums too.
  EXPECT_LT((two.second.rowwise().sum() + two.first.rowwise().sum()).norm(), 1e-12 * scale * two.second.cols());
}

TEST(Threads, ReducedBlocksFoldInBlockOrder) {
  // A max with ties keeps the first block's index, whatever the thread count: as one pass would.
  Eigen::VectorXd a = Eigen::VectorXd::Zero(1000);
  a[100] = a[700] = 5.0;
  for (int threads : {1, 2, 3, 8}) {
    const auto first_max = reduce_blocks<std::pair<double, Eigen::Index>>(
        threads, a.size(),
        [&](Eigen::Index begin, Eigen::Index end) {
          std::pair<double, Eigen::Index> best{-1.0, begin};
          for (Eigen::Index i = begin; i < end; ++i)
            if (a[i] > best.first) best = {a[i], i};
          return best;
        },
        [](auto x, auto y) { return y.first > x.first ? y : x; });
    EXPECT_EQ(first_max.second, 100) << threads << " threads";
  }
  // Every block is visited once: a sum of integers is exact.
  for (int threads : {1, 2, 5})
    EXPECT_EQ(reduce_blocks<double>(
                  threads, 1001, [](Eigen::Index b, Eigen::Index e) { return double((e - 1) * e / 2 - (b - 1) * b / 2); },
                  std::plus<double>()),
              1000.0 * 1001 / 2);
}

TEST(Threads, AStepIsReproducibleForACountAndAgreesWithOneThreadToRoundOff) {
  if (!built_with_openmp()) GTEST_SKIP() << "built without OpenMP: only one thread";
  Params p = cellsim::testing::small_cell_case();
  const Tissue cell = build_tissue(p);
  const auto run = [&](int threads) {
    Simulation sim(p, cell);
    sim.set_threads(threads);
    for (int n = 0; n < 20; ++n) sim.step();
    return sim.state();
  };
  const State one = run(1), two = run(2), two_again = run(2);
  EXPECT_TRUE(two.fluid.x == two_again.fluid.x && two.wall.x == two_again.wall.x && two.fluid.m == two_again.fluid.m);
  const double size = 40e-6;
  EXPECT_LT((two.fluid.x - one.fluid.x).cwiseAbs().maxCoeff(), 1e-12 * size);
  EXPECT_LT((two.wall.x - one.wall.x).cwiseAbs().maxCoeff(), 1e-12 * size);
  EXPECT_GT((one.fluid.x - cell.fluid_x).cwiseAbs().maxCoeff(), 0.0);  // the particles moved
}

TEST(Threads, NeighbourListsAreTheSameForAnyThreadCount) {
  if (!built_with_openmp()) GTEST_SKIP() << "built without OpenMP: only one thread";
  const ShakenCell s;
  const auto lists = [&](int threads) {
    NeighbourLists l(0.15 * *s.p.h0_m);
    l.update(s.cell.fluid_x, s.wall.x, 2.0 * *s.p.h0_m, 1.5 * *s.p.h0_m, threads);
    return l;
  };
  const NeighbourLists one = lists(1);
  ASSERT_GT(one.fluid_fluid().pairs, 10000u);
  ASSERT_GT(one.fluid_wall().pairs, 1000u);
  for (int threads : {2, 3}) {
    const NeighbourLists many = lists(threads);
    EXPECT_EQ(many.fluid_fluid().offset, one.fluid_fluid().offset) << threads << " threads";
    EXPECT_EQ(many.fluid_fluid().index, one.fluid_fluid().index) << threads << " threads";
    EXPECT_EQ(many.fluid_fluid().pairs, one.fluid_fluid().pairs);
    EXPECT_EQ(many.fluid_wall().offset, one.fluid_wall().offset) << threads << " threads";
    EXPECT_EQ(many.fluid_wall().index, one.fluid_wall().index) << threads << " threads";
    EXPECT_EQ(many.fluid_wall().pairs, one.fluid_wall().pairs);
  }
}

TEST(Threads, FluidPairSumsFollowEveryNewList) {
  // The halos are kept from one step to the next; a rebuilt list (of any NeighbourLists) must renew them.
  if (!built_with_openmp()) GTEST_SKIP() << "built without OpenMP: only one thread";
  const ShakenCell s;
  const CubicSplineKernel kernel(*s.p.h0_m);
  const EquationOfState eos{2e5, 20e6, 1000, 7};
  FluidParticles f;
  f.x = s.cell.fluid_x;
  f.v = Eigen::Matrix3Xd::Random(3, f.x.cols());
  f.m = Eigen::VectorXd::Constant(f.x.cols(), s.cell.fluid_mass_kg);
  f.rho = Eigen::VectorXd::Constant(f.x.cols(), 1000.0);
  FluidParticles moved = f;
  moved.x.array() += 0.3 * *s.p.h0_m * Eigen::Matrix3Xd::Random(3, f.x.cols()).array();
  NeighbourLists first(0.15 * *s.p.h0_m), second(0.15 * *s.p.h0_m);
  first.update(f.x, s.wall.x, kernel.support(), 0.0, 2);
  second.update(moved.x, s.wall.x, kernel.support(), 0.0, 2);
  FluidRates kept, fresh;
  fluid_pair_terms(f, first.fluid_fluid(), kernel, eos, 0.1, 2, kept);
  fluid_pair_terms(moved, second.fluid_fluid(), kernel, eos, 0.1, 2, kept);  // the same scratch, a new list
  fluid_pair_terms(moved, second.fluid_fluid(), kernel, eos, 0.1, 2, fresh);
  EXPECT_TRUE(kept.force == fresh.force && kept.drho_dt == fresh.drho_dt);
}
