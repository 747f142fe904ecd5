#pragma once
// The stages' caps (drying.steps, compression.steps; model.md §5-6) default to durations, so that a
// case run at another time step (a resolution level, a time-step study) needs no caps of its own.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <sstream>

#include "core/errors.hpp"
#include "core/params.hpp"

namespace cellsim {

inline constexpr double kDryingCapTime_s = 80e-6;       // the paper's 80 000 steps of 1 ns
inline constexpr double kCompressionCapTime_s = 25e-6;  // 25 000 steps of 1 ns: strain 0.15 at 1 m/s
inline constexpr double kCapReferenceSpeed_m_s = 1.0;     // plates slower than this get the same travel

// Fills in the caps a case leaves to auto: the duration over time.dt_ns, rounded. A plate slower than
// 1 m/s gets as much travel as one at 1 m/s (25 us x 1 m/s / speed; faster ones keep the 25 us), and a
// load-unload (compression.unload_at_strain) adds the way back: the loading's time x plate speed /
// unload speed.
// A derived cap is held to its key's range (at most 1e9 steps, as a cap typed in the file): a time step
// or a plate speed that would ask for more is refused, naming what derived it.
inline constexpr double kMostStageSteps = 1e9;

inline std::int64_t derived_cap(const char* key, double duration_s, const Params& p, const char* from) {
  const double steps = duration_s / p.dt_s;
  if (!(steps <= kMostStageSteps)) {
    std::ostringstream msg;
    msg << key << " = auto: " << duration_s * 1e6 << " us at time.dt_ns = " << p.dt_s * 1e9 << from << " is " << steps
        << " steps, more than the " << kMostStageSteps << " a stage may take; give " << key << " or a larger time.dt_ns";
    throw InputError(msg.str());
  }
  return std::llround(steps);
}

inline void resolve_stage_caps(Params& p) {
  if (!p.drying_steps) p.drying_steps = derived_cap("drying.steps", kDryingCapTime_s, p, "");
  const double loading_time_s = kCompressionCapTime_s * std::max(1.0, kCapReferenceSpeed_m_s / p.plate_speed_m_s);
  const double unload_share = p.unload_at_strain ? p.plate_speed_m_s / *p.unload_speed_m_s : 0.0;
  if (!p.compression_steps)
    p.compression_steps = derived_cap("compression.steps", loading_time_s * (1.0 + unload_share), p,
                                      " (and compression.plate_speed_m_s, unload_speed_m_s)");
}

// compression.unload_speed_m_s defaults to the loading speed; a plate that turns back must turn before
// compression.end_strain stops the run.
inline void resolve_unloading(Params& p) {
  if (!p.unload_speed_m_s) p.unload_speed_m_s = p.plate_speed_m_s;
  if (p.unload_at_strain && p.end_strain && *p.unload_at_strain >= *p.end_strain) {
    std::ostringstream msg;
    msg << "compression.unload_at_strain = " << *p.unload_at_strain << ": the plate must turn before "
        << "compression.end_strain = " << *p.end_strain << " stops the compression (give a smaller value, or a "
        << "larger end_strain)";
    throw InputError(msg.str());
  }
}

}  // namespace cellsim
