// Plate-wall force, Eq 22: exactly k_pw (r_pw - d) within r_pw and the footprint, nothing
// outside; the plates feel the reaction.
#include <gtest/gtest.h>

#include "physics/plate_motion.hpp"
#include "physics/plates.hpp"

using namespace cellsim;

TEST(Plates, ForceIsLinearInOverlapInsideFootprintOnly) {
  const PlateLaw law{3e-6, 1e3, 150e-6, 150e-6};
  Plates plates;
  plates.active = true;
  plates.bottom_z_m = -70e-6;
  plates.top_z_m = 70e-6;
  Eigen::Matrix3Xd x(3, 6);
  x.col(0) << 0, 0, 68e-6;        // 2 um below the top plate: inside r_pw
  x.col(1) << 10e-6, 5e-6, -69e-6;  // 1 um above the bottom plate
  x.col(2) << 0, 0, 60e-6;        // 10 um from the top plate: no force
  x.col(3) << 80e-6, 0, 68.5e-6;  // beyond the footprint in x (|x| > 75 um)
  x.col(4) << 0, -76e-6, -69.5e-6;  // beyond the footprint in y
  x.col(5) << 74e-6, 74e-6, 69e-6;  // just inside the footprint's corner
  Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, 6);
  add_plate_forces(x, law, plates, f);
  // d is the particle's distance to the plate plane, computed as the solver does.
  const auto overlap_force = [&](double d) { return law.stiffness_N_m * (law.range_m - d); };
  EXPECT_EQ(f(2, 0), -overlap_force(plates.top_z_m - x(2, 0)));
  EXPECT_EQ(f(2, 1), overlap_force(x(2, 1) - plates.bottom_z_m));
  EXPECT_NEAR(f(2, 0), -1e3 * 1e-6, 1e-15);  // = k_pw (r_pw - d) with d = 2 um
  EXPECT_EQ(f.col(2).norm(), 0.0);
  EXPECT_EQ(f.col(3).norm(), 0.0);
  EXPECT_EQ(f.col(4).norm(), 0.0);
  EXPECT_EQ(f(2, 5), -overlap_force(plates.top_z_m - x(2, 5)));
  EXPECT_EQ(f.topRows<2>().norm(), 0.0);  // vertical only
  EXPECT_EQ(plates.contacts, 3);
  EXPECT_DOUBLE_EQ(plates.force_top_N, -(f(2, 0) + f(2, 5)));  // reaction on the top plate
  EXPECT_DOUBLE_EQ(plates.force_bottom_N, f(2, 1));
}

// The top plate's schedule (plate_motion.hpp): down at the plate speed, and after the turn up at the
// unload speed from where it turned; its speed (for the plate's work) changes sign at the turn.
TEST(PlateMotion, ThePlateGoesDownThenTurnsBackFromWhereItIs) {
  Plates plates;
  plates.active = true;
  plates.top_start_z_m = 100e-6;
  plates.start_time_s = 2e-6;
  const PlateMotion loading_only{1.0, std::nullopt, 1.0};
  EXPECT_FALSE(awaits_turn(plates, loading_only));
  const PlateMotion m{2.0, 0.1, 0.5};
  EXPECT_TRUE(awaits_turn(plates, m));
  EXPECT_DOUBLE_EQ(top_plate_z_m(plates, m, 7e-6), 100e-6 - 2.0 * 5e-6);
  EXPECT_EQ(top_plate_speed_m_s(plates, m), 2.0);
  plates.top_z_m = top_plate_z_m(plates, m, 7e-6);
  turn_top_plate(plates, 7e-6);
  EXPECT_FALSE(awaits_turn(plates, m));
  EXPECT_DOUBLE_EQ(top_plate_z_m(plates, m, 7e-6), 90e-6);
  EXPECT_DOUBLE_EQ(top_plate_z_m(plates, m, 11e-6), 90e-6 + 0.5 * 4e-6);
  EXPECT_EQ(top_plate_speed_m_s(plates, m), -0.5);
}
