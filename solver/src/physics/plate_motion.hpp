#pragma once
// The top plate's schedule (model.md §6): down at compression.plate_speed_m_s from the start of
// compression; with compression.unload_at_strain, back up at compression.unload_speed_m_s from the moment
// the cell reached that strain (Plates::unload_start_*). The bottom plate stays.
#include <optional>

#include "core/params.hpp"
#include "core/state.hpp"

namespace cellsim {

struct PlateMotion {
  double down_speed_m_s = 0;
  std::optional<double> turn_at_strain;  // none: the plate only loads
  double up_speed_m_s = 0;
};

inline PlateMotion plate_motion(const Params& p) {
  return {p.plate_speed_m_s, p.unload_at_strain, p.unload_speed_m_s.value_or(p.plate_speed_m_s)};
}

// The top plate's height at time t.
inline double top_plate_z_m(const Plates& plates, const PlateMotion& m, double t) {
  return plates.unloading ? plates.unload_start_z_m + m.up_speed_m_s * (t - plates.unload_start_time_s)
                          : plates.top_start_z_m - m.down_speed_m_s * (t - plates.start_time_s);
}

// Its downward speed: the plate's work on the wall is the top force times this (negative while it unloads).
inline double top_plate_speed_m_s(const Plates& plates, const PlateMotion& m) {
  return plates.unloading ? -m.up_speed_m_s : m.down_speed_m_s;
}

// Whether the plate is still to turn: the caller then measures the strain and calls turn_top_plate.
inline bool awaits_turn(const Plates& plates, const PlateMotion& m) {
  return plates.active && !plates.unloading && m.turn_at_strain.has_value();
}

// Turns the plate back up at time t, from where it is.
inline void turn_top_plate(Plates& plates, double t) {
  plates.unloading = true;
  plates.unload_start_time_s = t;
  plates.unload_start_z_m = plates.top_z_m;
}

}  // namespace cellsim
