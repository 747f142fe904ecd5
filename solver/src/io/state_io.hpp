#pragma once
// Saving and loading the state a run can continue from (/state in a result file), and the time
// series already recorded (so a continued run's file holds the whole history).
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/state.hpp"
#include "engine/measures.hpp"
#include "io/compression_summary.hpp"
#include "io/drying_summary.hpp"
#include "io/h5.hpp"

namespace cellsim {

void write_state(hid_t parent, const State& s);

// How the run went, as attributes of `parent`: the drying summary (settle_*, drying_steady,
// drying_steady_time_s), the compression's (compression_reached_end, compression_end_strain), and the
// warning that joins theirs.
void write_run_summary(hid_t parent, const DryingSummary& d, const CompressionSummary& c);

struct SavedRun {
  State state;
  std::vector<Record> records;
  nlohmann::json case_doc;  // the case it ran, resolved (its case_json attribute)
  DryingSummary drying;
  int threads = 1;  // the threads it ran on: a run continued on another count agrees to round-off only
};

// Reads a complete result file; throws InputError if it is missing, incomplete or malformed.
SavedRun read_saved_run(const std::string& path);

// Throws InputError unless a saved state fits the case that `built` is the state of (with wall_bonds
// bonds): its particles, bonds and period, every array of them as long, and every value finite (positive
// densities and masses). A run checks a state it continues from before it writes anything.
void check_restorable(const State& saved, const State& built, std::size_t wall_bonds);

}  // namespace cellsim
