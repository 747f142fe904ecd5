#include "engine/steady_state.hpp"

#include <algorithm>
#include <cmath>

namespace cellsim {

double default_steady_rms_speed_m_s(Choice coupling_model) { return coupling_model == kPressure ? 0.05 : 0.02; }

void resolve_steady_state_defaults(Params& p) {
  if (!p.steady_rms_speed_m_s) p.steady_rms_speed_m_s = default_steady_rms_speed_m_s(p.coupling_model);
}

SteadyStateCriterion steady_state_criterion(const Params& p) {
  // A cell without turgor is judged against 1 kPa, so that its tolerance is not zero.
  const double pressure_scale_Pa = std::max(p.turgor_Pa, 1e3);
  return {p.turgor_Pa * p.dryness,
          p.steady_pressure_tolerance * pressure_scale_Pa,
          p.steady_volume_tolerance,
          p.steady_rms_speed_m_s.value_or(default_steady_rms_speed_m_s(p.coupling_model)),
          p.steady_window_s,
          p.dryness < 1.0 ? p.ramp_time_s : 0.0};  // a fresh cell has nothing to ramp
}

bool is_steady(const std::vector<Record>& records, const SteadyStateCriterion& c) {
  if (records.empty()) return false;
  const double now = records.back().time_s;
  const double window_start = now - c.window_s;
  // Half a nanosecond of slack: record times are sums of dt and carry round-off.
  if (window_start < c.earliest_s - 0.5e-9 || records.front().time_s > window_start + 0.5e-9) return false;
  double v_min = INFINITY, v_max = -INFINITY;
  for (auto r = records.rbegin(); r != records.rend() && r->time_s >= window_start - 0.5e-9; ++r) {
    if (std::abs(r->mean_pressure_Pa - c.target_pressure_Pa) > c.pressure_tolerance_Pa) return false;
    if (2.0 * r->kinetic_energy_fluid_J > c.rms_speed_m_s * c.rms_speed_m_s * r->fluid_mass_kg) return false;
    v_min = std::min(v_min, r->volume_m3);
    v_max = std::max(v_max, r->volume_m3);
  }
  return v_max - v_min <= c.volume_tolerance * records.back().volume_m3;
}

}  // namespace cellsim
