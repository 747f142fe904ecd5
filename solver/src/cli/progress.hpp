#pragma once
// Progress lines on stderr for long runs: steps, simulated time, wall time and ETA, at most one
// line per interval of wall-clock time. Counts the steps this process runs (a run continued with
// --from counts its compression only), against the steps planned; a stage that ends early (drying
// at steady state, compression at its end strain) gives back the steps it did not use. A stage aimed
// at a goal (a compression to its end strain) says how far it is, and its ETA follows the goal: a slab
// compressed to strain 0.12 stops at a third to a half of its step cap.
#include <chrono>
#include <cstdint>
#include <string>

namespace cellsim {

class Progress {
 public:
  Progress(std::int64_t planned_steps, double interval_s, bool quiet);
  // From the next step on, the line reports `quantity` against `goal` (e.g. "strain", 0.12), and the ETA
  // is the time to reach it at the pace since then, if sooner than the steps left.
  void aim(const std::string& quantity, double goal);
  // One step done, `reached` the aimed quantity after it; prints if the interval passed.
  void step(double time_s, const std::string& stage, double reached = 0.0);
  void unplan(std::int64_t steps) { planned_ -= steps; }  // steps a stage ended without
  void finish(double time_s);
  std::int64_t done() const { return done_; }
  std::int64_t planned() const { return planned_; }
  std::string line(double time_s, const std::string& stage) const;  // what step() prints

 private:
  using Clock = std::chrono::steady_clock;
  double elapsed_s() const;
  double eta_s() const;
  std::int64_t planned_, done_ = 0;
  std::string quantity_;  // empty: no goal
  double goal_ = 0, first_reached_ = 0, reached_ = 0;
  std::int64_t aimed_steps_ = -1;  // steps done since aim(); -1: none yet
  Clock::time_point aimed_at_;
  double interval_s_;
  bool quiet_;
  Clock::time_point start_, last_;
};

}  // namespace cellsim
