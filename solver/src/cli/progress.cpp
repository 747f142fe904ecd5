#include "cli/progress.hpp"

#include <algorithm>
#include <cstdio>

namespace cellsim {

Progress::Progress(std::int64_t planned_steps, double interval_s, bool quiet)
    : planned_(planned_steps), interval_s_(interval_s), quiet_(quiet), start_(Clock::now()), last_(start_) {}

double Progress::elapsed_s() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

void Progress::aim(const std::string& quantity, double goal) {
  quantity_ = quantity;
  goal_ = goal;
  aimed_steps_ = -1;
}

// The steps left at the pace so far; with a goal, the time to it at the pace since aim(), if sooner
// (the pace of the first step after aim() is not yet known: it is where the count starts).
double Progress::eta_s() const {
  const double elapsed = elapsed_s();
  double eta = done_ > 0 ? elapsed * static_cast<double>(planned_ - done_) / done_ : 0.0;
  if (!quantity_.empty() && aimed_steps_ > 0 && reached_ > first_reached_) {
    const double since_aim = std::chrono::duration<double>(Clock::now() - aimed_at_).count();
    eta = std::min(eta, std::max(0.0, since_aim * (goal_ - reached_) / (reached_ - first_reached_)));
  }
  return eta;
}

std::string Progress::line(double time_s, const std::string& stage) const {
  char goal[96] = "";
  if (!quantity_.empty())
    std::snprintf(goal, sizeof goal, ", %s %.4f of %g", quantity_.c_str(), reached_, goal_);
  char text[320];
  std::snprintf(text, sizeof text, "cellsim: %s step %lld/%lld (%.0f%%)%s, t = %.2f us, %.1f s elapsed, ETA %.1f s",
                stage.c_str(), static_cast<long long>(done_), static_cast<long long>(planned_),
                planned_ > 0 ? 100.0 * done_ / planned_ : 100.0, goal, time_s * 1e6, elapsed_s(), eta_s());
  return text;
}

void Progress::step(double time_s, const std::string& stage, double reached) {
  ++done_;
  reached_ = reached;
  if (!quantity_.empty() && ++aimed_steps_ == 0) {
    first_reached_ = reached;
    aimed_at_ = Clock::now();
  }
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
