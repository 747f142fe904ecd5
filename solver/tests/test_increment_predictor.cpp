// Where a quasi-static increment's relaxation starts (engine/increment_predictor.hpp): the plates'
// predictor keeps each particle's overlap, and the secant's motion has no sideways translation.
#include <gtest/gtest.h>

#include "engine/increment_predictor.hpp"

using namespace cellsim;

namespace {
Plates plates_at(double bottom_z_m, double top_z_m) {
  Plates plates;
  plates.active = true;
  plates.bottom_z_m = bottom_z_m;
  plates.top_z_m = top_z_m;
  return plates;
}
}  // namespace

// The top plate moves down 1 um (r_pw 3 um): a particle it touched 2 um deep moves down with it and keeps
// its 2 um; one it reaches anew sits at the edge of its range; one it does not reach, or one outside the
// footprint, stays where it was; the bottom plate did not move, so its particle stays.
TEST(IncrementPredictor, EachParticleKeepsItsPlateOverlap) {
  const PlateLaw law{3e-6, 1e3, 150e-6, 150e-6};
  const Plates before = plates_at(-70e-6, 70e-6), after = plates_at(-70e-6, 69e-6);
  Eigen::Matrix3Xd was(3, 5);
  was.col(0) << 0, 0, 69e-6;      // 1 um below the top plate: 2 um deep in its range
  was.col(1) << 0, 0, 66.5e-6;    // 3.5 um below: out of range before, 0.5 um in after
  was.col(2) << 0, 0, 60e-6;      // 9 um below: out of range after too
  was.col(3) << 80e-6, 0, 69e-6;  // beyond the footprint
  was.col(4) << 0, 0, -68e-6;     // 2 um above the bottom plate
  Eigen::Matrix3Xd x = was;
  keep_plate_overlaps(x, x, law, before, after);
  EXPECT_NEAR(x(2, 0), 68e-6, 1e-18);
  EXPECT_NEAR(x(2, 1), after.top_z_m - law.range_m, 1e-18);
  EXPECT_EQ(x(2, 2), was(2, 2));
  EXPECT_EQ(x(2, 3), was(2, 3));
  EXPECT_EQ(x(2, 4), was(2, 4));
  EXPECT_EQ(x.topRows<2>(), was.topRows<2>());
  EXPECT_NEAR(plate_overlap(x.col(0), law, after).top_m, plate_overlap(was.col(0), law, before).top_m, 1e-18);

  // From another start (the secant's): the overlap it had at was, not the one it has now.
  Eigen::Matrix3Xd ahead = was;
  ahead(2, 0) = 69.5e-6;  // the secant carried it 0.5 um up, 3.5 um deep after the move
  keep_plate_overlaps(ahead, was, law, before, after);
  EXPECT_NEAR(ahead(2, 0), 68e-6, 1e-18);
}

// An increment's motion, a deformation plus a sideways translation (3, -4) um and a vertical one: the
// secant keeps the deformation and the vertical motion, and drops the mean sideways part (a free motion
// between frictionless plates that would carry the cell to the plates' edge).
TEST(IncrementPredictor, TheSecantsMotionHasNoSidewaysTranslation) {
  Eigen::Matrix3Xd deformation(3, 4);
  deformation << 1, -1, 2, -2,  //
      0.5, 0.5, -0.5, -0.5,     //
      -1, -2, 0, 1;
  deformation *= 1e-7;
  Eigen::Matrix3Xd motion = deformation;
  motion.row(0).array() += 3e-6;
  motion.row(1).array() -= 4e-6;
  const Eigen::Matrix3Xd secant = secant_motion(motion);
  EXPECT_NEAR(secant.row(0).mean(), 0.0, 1e-20);
  EXPECT_NEAR(secant.row(1).mean(), 0.0, 1e-20);
  EXPECT_TRUE(secant.isApprox(deformation, 1e-12));
  EXPECT_EQ(secant.row(2), motion.row(2));
}
