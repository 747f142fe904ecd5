#include "progress.hpp"

#include <cstdio>

namespace cellsim {

Progress::Progress(std::int64_t total_steps, double interval_s, bool quiet)
    : total_(total_steps), interval_s_(interval_s), quiet_(quiet), start_(Clock::now()), last_(start_) {}

double Progress::elapsed_s() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

void Progress::update(std::int64_t steps_done, double time_s, const std::string& stage) {
  if (quiet_) return;
  const auto now = Clock::now();
  if (std::chrono::duration<double>(now - last_).count() < interval_s_) return;
  last_ = now;
  const double elapsed = elapsed_s();
  const double eta = steps_done > 0 ? elapsed * static_cast<double>(total_ - steps_done) / steps_done : 0.0;
  std::fprintf(stderr, "cellsim: %s step %lld/%lld (%.0f%%), t = %.2f us, %.1f s elapsed, ETA %.1f s\n", stage.c_str(),
               static_cast<long long>(steps_done), static_cast<long long>(total_),
               total_ ? 100.0 * steps_done / total_ : 100.0, time_s * 1e6, elapsed, eta);
}

void Progress::finish(std::int64_t steps_done, double time_s) {
  if (quiet_) return;
  const double elapsed = elapsed_s();
  std::fprintf(stderr, "cellsim: done, %lld steps, t = %.2f us, %.1f s wall time (%.3f ms/step)\n",
               static_cast<long long>(steps_done), time_s * 1e6, elapsed,
               steps_done ? 1e3 * elapsed / steps_done : 0.0);
}

}  // namespace cellsim
