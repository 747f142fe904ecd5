#pragma once
// When drying has ended (model.md §5: "once the cell reached its steady state ... the compression
// was initiated"): over the last window of records, the mean fluid pressure stays near its target
// P_T(X), the enclosed volume has stopped changing, and the fluid is at rest. Judged only once the
// drying ramp is over. Every threshold is a case key (drying.steady_*).
#include <vector>

#include "engine/measures.hpp"

namespace cellsim {

struct SteadyStateCriterion {
  double target_pressure_Pa;     // P_T(X) = P_T0 X
  double pressure_tolerance_Pa;  // |P_mean - target| at every record of the window
  double volume_tolerance;       // (V_max - V_min) / V over the window
  double rms_speed_m_s;          // sqrt(2 KE_fluid / M_fluid) at every record of the window
  double window_s;
  double earliest_s;             // the window may not begin before this (the end of the ramp)
};

SteadyStateCriterion steady_state_criterion(const Params& p);

// True if the records, the last one being now, show a steady state over the whole window.
bool is_steady(const std::vector<Record>& records, const SteadyStateCriterion& c);

}  // namespace cellsim
