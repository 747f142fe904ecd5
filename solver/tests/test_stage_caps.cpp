// The stages' caps left to auto (engine/stage_caps.hpp): a duration over the time step, as much plate
// travel for a slow plate as for one at 1 m/s, and the way back of a load-unload.
#include <gtest/gtest.h>

#include "core/params.hpp"
#include "engine/stage_caps.hpp"

using cellsim::Params;
using cellsim::resolve_stage_caps;

namespace {
Params caps_for(double plate_speed_m_s, double dt_ns) {
  Params p;
  p.plate_speed_m_s = plate_speed_m_s;
  p.dt_s = dt_ns * 1e-9;
  resolve_stage_caps(p);
  return p;
}
}  // namespace

TEST(StageCaps, AtOneMetrePerSecondOrFasterTheCompressionLasts25MicrosecondsAtAnyTimeStep) {
  EXPECT_EQ(*caps_for(1.0, 1.0).compression_steps, 25000);
  EXPECT_EQ(*caps_for(1.0, 0.5).compression_steps, 50000);
  EXPECT_EQ(*caps_for(10.0, 1.0).compression_steps, 25000);
  EXPECT_EQ(*caps_for(1.0, 1.0).drying_steps, 80000);
}

TEST(StageCaps, ASlowerPlateGetsTheTravelOfOneAtOneMetrePerSecond) {
  // 25 um of travel: 100 us at 0.25 m/s, 250 us at 0.1 m/s.
  EXPECT_EQ(*caps_for(0.25, 1.0).compression_steps, 100000);
  EXPECT_EQ(*caps_for(0.1, 0.5).compression_steps, 500000);
}

TEST(StageCaps, ALoadUnloadAddsTheWayBackAtItsOwnSpeed) {
  Params p;
  p.plate_speed_m_s = 1.0;
  p.unload_at_strain = 0.15;
  p.unload_speed_m_s = 0.25;
  p.dt_s = 1e-9;
  resolve_stage_caps(p);
  EXPECT_EQ(*p.compression_steps, 125000);  // 25 us down, 100 us back up
}

TEST(StageCaps, ACapTheCaseGivesIsKept) {
  Params p;
  p.plate_speed_m_s = 0.1;
  p.dt_s = 1e-9;
  p.compression_steps = 1234;
  p.drying_steps = 99;
  resolve_stage_caps(p);
  EXPECT_EQ(*p.compression_steps, 1234);
  EXPECT_EQ(*p.drying_steps, 99);
}
