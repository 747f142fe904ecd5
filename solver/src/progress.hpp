#pragma once
// Progress lines on stderr for long runs: steps, simulated time, wall time and ETA, at most one
// line per interval of wall-clock time.
#include <chrono>
#include <cstdint>
#include <string>

namespace cellsim {

class Progress {
 public:
  Progress(std::int64_t total_steps, double interval_s, bool quiet);
  void update(std::int64_t steps_done, double time_s, const std::string& stage);
  void finish(std::int64_t steps_done, double time_s);
  double elapsed_s() const;

 private:
  using Clock = std::chrono::steady_clock;
  std::int64_t total_;
  double interval_s_;
  bool quiet_;
  Clock::time_point start_, last_;
};

}  // namespace cellsim
