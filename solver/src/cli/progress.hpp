#pragma once
// Progress lines on stderr for long runs: steps, simulated time, wall time and ETA, at most one
// line per interval of wall-clock time. Counts the steps this process runs (a run continued with
// --from counts its compression only), against the steps planned; a stage that ends early (drying
// at steady state, compression at its end strain) gives back the steps it did not use.
#include <chrono>
#include <cstdint>
#include <string>

namespace cellsim {

class Progress {
 public:
  Progress(std::int64_t planned_steps, double interval_s, bool quiet);
  void step(double time_s, const std::string& stage);  // one step done; prints if the interval passed
  void unplan(std::int64_t steps) { planned_ -= steps; }  // steps a stage ended without
  void finish(double time_s);
  std::int64_t done() const { return done_; }
  std::int64_t planned() const { return planned_; }
  std::string line(double time_s, const std::string& stage) const;  // what step() prints

 private:
  using Clock = std::chrono::steady_clock;
  double elapsed_s() const;
  std::int64_t planned_, done_ = 0;
  double interval_s_;
  bool quiet_;
  Clock::time_point start_, last_;
};

}  // namespace cellsim
