// `cellsim bench` (issue: performance, item 1): the median ms per step, particle-steps per second and
// a time for every phase, whose sum accounts for the step.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "cli_helpers.hpp"
#include "phase_timer.hpp"

using cellsim::testing::run_cli;
using cellsim::testing::ScratchDir;

TEST(Bench, PrintsTheMedianStepAndEveryPhaseThatAddUpToIt) {
  ScratchDir dir("bench");
  const auto c = dir.write("case.json", R"({"cell": {"n_wall": 402, "n_fluid": 400}, "output": {"record_every": 50}})");
  const auto r = run_cli({"bench", c, "--steps", "300", "--repeats", "3"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(median ([\d.]+) ms/step .*, ([\d.]+) million particle-steps/s)")))
      << r.out;
  const double total_ms = std::stod(m[1]), rate = std::stod(m[2]);
  EXPECT_GT(total_ms, 0.0);
  EXPECT_NEAR(rate, 802 / total_ms * 1e-3, 0.01 * rate);  // 402 + 400 particles
  double phases_ms = 0;
  for (const char* name : cellsim::kPhaseNames) {
    const auto at = r.out.find(name);
    ASSERT_NE(at, std::string::npos) << "no phase '" << name << "' in\n" << r.out;
    std::istringstream line(r.out.substr(at + std::string(name).size()));
    double ms = -1;
    line >> ms;
    EXPECT_GE(ms, 0.0) << name;
    phases_ms += ms;
  }
  // Medians of parts need not add up to the median of the whole exactly; the clock reads between
  // phases are the only time not in some phase.
  EXPECT_GT(phases_ms, 0.7 * total_ms) << r.out;
  EXPECT_LT(phases_ms, 1.1 * total_ms) << r.out;
}
