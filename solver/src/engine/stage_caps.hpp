#pragma once
// The stages' caps (drying.steps, compression.steps; model.md §5-6) default to durations, so that a
// case run at another time step (a resolution level, a time-step study) needs no caps of its own.
#include <cmath>

#include "core/params.hpp"

namespace cellsim {

inline constexpr double kDryingCapTime_s = 80e-6;       // the paper's 80 000 steps of 1 ns
inline constexpr double kCompressionCapTime_s = 25e-6;  // 25 000 steps of 1 ns: strain 0.15 at 1 m/s

// Fills in the caps a case leaves to auto: the duration over time.dt_ns, rounded.
inline void resolve_stage_caps(Params& p) {
  if (!p.drying_steps) p.drying_steps = std::llround(kDryingCapTime_s / p.dt_s);
  if (!p.compression_steps) p.compression_steps = std::llround(kCompressionCapTime_s / p.dt_s);
}

}  // namespace cellsim
