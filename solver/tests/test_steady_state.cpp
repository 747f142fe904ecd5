// When drying ends (steady_state.hpp): every criterion must hold over the whole window, after the
// ramp; one record off its target, a volume still moving, or a fluid still in motion is not steady.
#include <gtest/gtest.h>

#include <vector>

#include "engine/steady_state.hpp"
#include "io/case_file.hpp"

using namespace cellsim;

namespace {

const SteadyStateCriterion kCriterion{100e3, 1e3, 5e-4, 0.02, 5e-6, 20e-6};

// Records every 0.1 us up to t_end, at rest on the target unless changed afterwards.
std::vector<Record> records_until(double t_end_us) {
  std::vector<Record> r;
  for (int k = 0; k * 0.1 <= t_end_us + 1e-9; ++k) {
    Record rec{};
    rec.time_s = k * 0.1e-6;
    rec.mean_pressure_Pa = 100e3;
    rec.volume_m3 = 1e-12;
    rec.fluid_mass_kg = 1e-9;
    rec.kinetic_energy_fluid_J = 0.5 * 1e-9 * 0.01 * 0.01;  // rms speed 0.01 m/s
    r.push_back(rec);
  }
  return r;
}

}  // namespace

TEST(SteadyState, HoldsWhenEveryCriterionHoldsOverTheWholeWindowAfterTheRamp) {
  EXPECT_TRUE(is_steady(records_until(30), kCriterion));
  EXPECT_FALSE(is_steady(records_until(24.5), kCriterion));  // the window would begin inside the ramp
  EXPECT_FALSE(is_steady({}, kCriterion));
}

TEST(SteadyState, OneRecordOffTargetInTheWindowIsNotSteady) {
  auto r = records_until(30);
  r[r.size() - 20].mean_pressure_Pa = 101.5e3;  // 1.5 kPa off, tolerance 1 kPa
  EXPECT_FALSE(is_steady(r, kCriterion));
  r[r.size() - 20].mean_pressure_Pa = 100.9e3;
  EXPECT_TRUE(is_steady(r, kCriterion));
  r[r.size() - 60].mean_pressure_Pa = 150e3;  // before the window: no matter
  EXPECT_TRUE(is_steady(r, kCriterion));
}

TEST(SteadyState, AVolumeStillChangingOrAFluidStillMovingIsNotSteady) {
  auto r = records_until(30);
  r.back().volume_m3 = 1.0006e-12;  // 0.06 % spread, tolerance 0.05 %
  EXPECT_FALSE(is_steady(r, kCriterion));
  r = records_until(30);
  r[r.size() - 3].kinetic_energy_fluid_J = 0.5 * 1e-9 * 0.03 * 0.03;  // rms 0.03 m/s
  EXPECT_FALSE(is_steady(r, kCriterion));
}

TEST(SteadyState, TheCriterionComesFromTheCaseAndWaitsForTheRampOnlyWhenSomethingRamps) {
  Params dried = validate_case(nlohmann::json::parse(R"({"drying": {"dryness": 0.5}})"));
  const SteadyStateCriterion c = steady_state_criterion(dried);
  EXPECT_DOUBLE_EQ(c.target_pressure_Pa, 100e3);     // P_T0 X
  EXPECT_DOUBLE_EQ(c.pressure_tolerance_Pa, 1e3);    // 0.5 % of P_T0 = 200 kPa
  EXPECT_DOUBLE_EQ(c.window_s, 5e-6);
  EXPECT_DOUBLE_EQ(c.earliest_s, 20e-6);             // the ramp
  Params fresh = validate_case(nlohmann::json::parse(R"({"drying": {"dryness": 1.0}})"));
  EXPECT_EQ(steady_state_criterion(fresh).earliest_s, 0.0);
}

// The rms-speed threshold follows the coupling unless the case sets it (issue: a user who only switches
// the coupling gets a drying that can end): the pressure coupling's fluid at rest jitters at ~0.03 m/s.
TEST(SteadyState, TheRmsSpeedThresholdFollowsTheCouplingUnlessSet) {
  const auto threshold = [](const char* text) {
    const Params p = validate_case(nlohmann::json::parse(text));
    EXPECT_TRUE(p.steady_rms_speed_m_s.has_value()) << text;  // resolved, so result files record it
    return steady_state_criterion(p).rms_speed_m_s;
  };
  EXPECT_DOUBLE_EQ(threshold("{}"), 0.02);
  EXPECT_DOUBLE_EQ(threshold(R"({"coupling": {"model": "pressure"}})"), 0.05);
  EXPECT_DOUBLE_EQ(threshold(R"({"coupling": {"model": "pressure"}, "drying": {"steady_rms_speed_m_s": 0.03}})"), 0.03);
  EXPECT_DOUBLE_EQ(threshold(R"({"drying": {"steady_rms_speed_m_s": null}})"), 0.02);
}
