#pragma once
// Saving and loading the state a run can continue from (/state in a result file), and the time
// series already recorded (so a continued run's file holds the whole history).
#include <string>
#include <vector>

#include "core/state.hpp"
#include "engine/measures.hpp"
#include "io/drying_summary.hpp"
#include "io/h5.hpp"

namespace cellsim {

void write_state(hid_t parent, const State& s);

// The drying summary as attributes of `parent` (settle_*, drying_steady, drying_steady_time_s, warning).
void write_drying_summary(hid_t parent, const DryingSummary& d);

struct SavedRun {
  State state;
  std::vector<Record> records;
  std::string case_json;
  DryingSummary drying;
  int threads = 1;  // the threads it ran on: a run continued on another count agrees to round-off only
};

// Reads a complete result file; throws InputError if it is missing, incomplete or malformed.
SavedRun read_saved_run(const std::string& path);

}  // namespace cellsim
