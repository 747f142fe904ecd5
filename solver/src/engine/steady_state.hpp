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

// The rms speed below which a fluid counts as at rest, for a coupling: the fluid of the default cell
// at rest jitters at ~0.01 m/s rms with the LJ layer and ~0.03 with the pressure coupling
// (docs/model-closures.md), while drying transients run at 0.1-2 m/s.
double default_steady_rms_speed_m_s(Choice coupling_model);

// Fills in the drying keys that follow from the case (drying.steady_rms_speed_m_s), if unset.
void resolve_steady_state_defaults(Params& p);

SteadyStateCriterion steady_state_criterion(const Params& p);

// True if the records, the last one being now, show a steady state over the whole window.
bool is_steady(const std::vector<Record>& records, const SteadyStateCriterion& c);

}  // namespace cellsim
