// Neighbour lists (neighbours.hpp): they see every pair a brute-force search sees; trusting a step's
// displacement bound, they skip their pass over the positions while the reported bounds leave the
// skin unused, and every rebuild happens when the measured displacement calls for it, as without them.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "engine/simulation.hpp"
#include "geometry/neighbours.hpp"
#include "geometry/tissue.hpp"
#include "fluid_box.hpp"
#include "small_cell.hpp"

using namespace cellsim;
using cellsim::testing::fluid_box;

TEST(Neighbours, ListsContainEveryPairWithinTheCutoff) {
  const double dx = 7.7e-6;
  FluidParticles f = fluid_box(7, dx, 9);
  Eigen::Matrix3Xd wall = fluid_box(5, 1.6 * dx, 4).x;
  NeighbourLists lists(0.5e-6);
  const double rc_ff = 2.1 * dx, rc_fw = 1.3 * dx;
  lists.update(f.x, wall, rc_ff, rc_fw);
  // Move particles a little (less than half the skin) and check the lists still hold every pair.
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> nudge(-0.14e-6, 0.14e-6);
  for (Eigen::Index i = 0; i < f.size(); ++i) f.x.col(i) += Eigen::Vector3d(nudge(rng), nudge(rng), nudge(rng));
  EXPECT_FALSE(lists.update(f.x, wall, rc_ff, rc_fw));  // reused, not rebuilt
  const auto contains = [](const PairList& l, int i, int j) {
    return std::binary_search(l.index.begin() + l.offset[i], l.index.begin() + l.offset[i + 1], j);
  };
  int pairs = 0;
  for (int i = 0; i < f.size(); ++i) {
    for (int j = i + 1; j < f.size(); ++j)
      if ((f.x.col(i) - f.x.col(j)).norm() < rc_ff) {
        ++pairs;
        ASSERT_TRUE(contains(lists.fluid_fluid(), i, j)) << i << " " << j;
      }
    for (int k = 0; k < wall.cols(); ++k)
      if ((f.x.col(i) - wall.col(k)).norm() < rc_fw) ASSERT_TRUE(contains(lists.fluid_wall(), i, k)) << i << " " << k;
  }
  EXPECT_GT(pairs, 1000);
  // A larger move forces a rebuild.
  f.x.col(0) += Eigen::Vector3d(1e-6, 0, 0);
  EXPECT_TRUE(lists.update(f.x, wall, rc_ff, rc_fw));
}

TEST(Neighbours, AReportedDisplacementBoundSkipsTheCheckUntilTheSkinCouldBeUsedUp) {
  const double dx = 7.7e-6, skin = 0.5e-6, rc_ff = 2.1 * dx, rc_fw = 1.3 * dx;
  Eigen::Matrix3Xd fluid = fluid_box(6, dx, 1).x, wall = fluid_box(4, 1.6 * dx, 2).x;
  NeighbourLists lists(skin);
  ASSERT_TRUE(lists.update(fluid, wall, rc_ff, rc_fw));
  const auto move = [&](double distance) {
    fluid.row(0).array() += distance;
    wall.row(0).array() += distance;
  };
  // Each step moves every particle 0.05 um and reports at most 0.1 um: two such reports (2 x 0.2 um
  // against the 0.5 um skin) need no look at the positions.
  for (int step = 1; step <= 2; ++step) {
    move(0.05e-6);
    EXPECT_FALSE(lists.update(fluid, wall, rc_ff, rc_fw, 1, 0.1e-6)) << "step " << step;
    EXPECT_EQ(lists.displacement_checks(), 0) << "step " << step;
  }
  // A third would allow 2 x 0.3 um > 0.5 um: the lists measure 0.15 um, keep the lists, and go on
  // from the measured 0.15 um (so a 0.05 um report, 2 x 0.2 um in all, needs no look again).
  move(0.05e-6);
  EXPECT_FALSE(lists.update(fluid, wall, rc_ff, rc_fw, 1, 0.1e-6));
  EXPECT_EQ(lists.displacement_checks(), 1);
  move(0.05e-6);
  EXPECT_FALSE(lists.update(fluid, wall, rc_ff, rc_fw, 1, 0.05e-6));
  EXPECT_EQ(lists.displacement_checks(), 1);
  // No bound (the default): measured every time; a real move past the skin rebuilds.
  EXPECT_FALSE(lists.update(fluid, wall, rc_ff, rc_fw));
  EXPECT_EQ(lists.displacement_checks(), 2);
  move(0.1e-6);  // 0.3 um since the build
  EXPECT_TRUE(lists.update(fluid, wall, rc_ff, rc_fw, 1, 0.1e-6));
  EXPECT_EQ(lists.displacement_checks(), 3);
  EXPECT_EQ(lists.builds(), 2);
  // After a build, the bounds add up from zero again.
  EXPECT_FALSE(lists.update(fluid, wall, rc_ff, rc_fw, 1, 0.2e-6));
  EXPECT_EQ(lists.displacement_checks(), 3);
}

TEST(Neighbours, StepsThatTrustTheirDriftRebuildWhenStepsThatMeasureDo) {
  Params p = cellsim::testing::small_cell_case();
  const Tissue cell = build_tissue(p);
  Simulation trusting(p, cell), measuring(p, cell);
  constexpr int kSteps = 3000;
  for (int n = 0; n < kSteps; ++n) {
    trusting.step();
    measuring.mutable_state();  // forgets the drift's bound: the lists measure the displacement
    measuring.step();
  }
  // The same rebuilds (several of them), on far fewer looks at the positions, and the same bits.
  EXPECT_GE(trusting.neighbours().builds(), 3);
  EXPECT_EQ(trusting.neighbours().builds(), measuring.neighbours().builds());
  EXPECT_GE(measuring.neighbours().displacement_checks(), kSteps - measuring.neighbours().builds());
  EXPECT_LT(trusting.neighbours().displacement_checks(), kSteps / 5);
  const State &a = trusting.state(), &b = measuring.state();
  EXPECT_TRUE(a.fluid.x == b.fluid.x && a.fluid.v == b.fluid.v && a.fluid.rho == b.fluid.rho && a.fluid.m == b.fluid.m);
  EXPECT_TRUE(a.wall.x == b.wall.x && a.wall.v == b.wall.v);
}
