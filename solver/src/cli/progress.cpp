#include "cli/progress.hpp"

#include <cstdio>

namespace cellsim {

Progress::Progress(std::int64_t planned_steps, double interval_s, bool quiet)
    : planned_(planned_steps), interval_s_(interval_s), quiet_(quiet), start_(Clock::now()), last_(start_) {}

double Progress::elapsed_s() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

std::string Progress::line(double time_s, const std::string& stage) const {
  const double elapsed = elapsed_s();
  const double eta = done_ > 0 ? elapsed * static_cast<double>(planned_ - done_) / done_ : 0.0;
  char text[256];
  std::snprintf(text, sizeof text, "cellsim: %s step %lld/%lld (%.0f%%), t = %.2f us, %.1f s elapsed, ETA %.1f s",
                stage.c_str(), static_cast<long long>(done_), static_cast<long long>(planned_),
                planned_ > 0 ? 100.0 * done_ / planned_ : 100.0, time_s * 1e6, elapsed, eta);
  return text;
}

void Progress::step(double time_s, const std::string& stage) {
  ++done_;
  if (quiet_) return;
  const auto now = Clock::now();
  if (std::chrono::duration<double>(now - last_).count() < interval_s_) return;
  last_ = now;
  std::fprintf(stderr, "%s\n", line(time_s, stage).c_str());
}

void Progress::finish(double time_s) {
  if (quiet_) return;
  const double elapsed = elapsed_s();
  std::fprintf(stderr, "cellsim: done, %lld steps, t = %.2f us, %.1f s wall time (%.3f ms/step)\n",
               static_cast<long long>(done_), time_s * 1e6, elapsed, done_ ? 1e3 * elapsed / done_ : 0.0);
}

}  // namespace cellsim
