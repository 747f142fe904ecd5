#pragma once
// The tests' small cell: 162 wall and 120 fluid particles, 40 um across, dt 0.5 ns. Steps take
// microseconds, so a test can set up any state by hand and step it.
#include <nlohmann/json.hpp>

#include "io/case_file.hpp"

namespace cellsim::testing {

// The small cell's case, with extra keys merged in (e.g. {"fluid": {"viscosity_Pa_s": 50}}).
inline Params small_cell_case(const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json doc = {{"cell", {{"n_wall", 162}, {"n_fluid", 120}, {"diameter_um", 40}}}, {"time", {{"dt_ns", 0.5}}}};
  doc.merge_patch(extra);
  return validate_case(doc);
}

}  // namespace cellsim::testing
