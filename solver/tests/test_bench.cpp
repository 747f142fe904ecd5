// `cellsim bench` (issue: performance, item 1): the median ms per step, particle-steps per second and
// a time for every phase, whose sum accounts for the step.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "cli_helpers.hpp"
#include "engine/phase_timer.hpp"
#include "parallel/threads.hpp"

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

// The bench steps the scheme its case asks for (time.scheme): a closed cell's quasi-static steps each
// relax the wall, which the bench counts; the leapfrog says so.
TEST(Bench, StepsTheSchemeTheCaseAsksFor) {
  ScratchDir dir("bench_scheme");
  const auto quasi = dir.write("quasi.json", R"({"cell": {"n_wall": 162, "diameter_um": 40}, "fluid": {"model": "cavity"},
      "time": {"scheme": "quasi_static", "dt_ns": 200}, "output": {"record_every": 5}})");
  const auto r = run_cli({"bench", quasi, "--steps", "5", "--repeats", "1"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(scheme: quasi-static, ([\d.]+) force evaluations a step)")))
      << r.out;
  EXPECT_GE(std::stod(m[1]), 1.0);
  const auto leapfrog = dir.write("leapfrog.json", R"({"cell": {"n_wall": 402, "n_fluid": 400}, "output": {"record_every": 5}})");
  const auto d = run_cli({"bench", leapfrog, "--steps", "5", "--repeats", "1"}, dir);
  ASSERT_EQ(d.exit_code, 0) << d.err;
  EXPECT_NE(d.out.find("scheme: leapfrog"), std::string::npos) << d.out;
}

// --sizes: the case at the three resolution levels (2.83x and 8x the fluid, 2x and 4x the wall,
// half the time step at level 3) and as tissues of 8 and 27 of its cells, each on 1 and 2 threads,
// with one row per run.
TEST(Bench, SizesRunsTheThreeResolutionLevelsAndTwoTissuesOnOneAndTwoThreads) {
  ScratchDir dir("bench_sizes");
  const auto c = dir.write("case.json", R"({"cell": {"n_wall": 402, "n_fluid": 400}, "output": {"record_every": 50}})");
  const auto r = run_cli({"bench", c, "--sizes", "--steps", "400", "--repeats", "1"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::regex row(R"(\n\s*(L\d|\dx\dx\d)\s+(\d+)\s+(\d+)\s+([\d.]+)\s+(\d)\s+(\d+)\s+[\d.]+ \()");
  std::vector<std::smatch> rows;
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), row); it != std::sregex_iterator(); ++it) rows.push_back(*it);
  const int thread_counts = cellsim::built_with_openmp() ? 2 : 1;
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(5 * thread_counts)) << r.out;
  const std::string label[] = {"L1", "L2", "L3", "2x2x2", "3x3x3"};
  const long fluid[] = {400, 1131, 3200, 8 * 400, 27 * 400}, wall[] = {402, 804, 1608, 8 * 402, 27 * 402};
  const double dt_ns[] = {1, 1, 0.5, 1, 1};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::size_t size = i / static_cast<std::size_t>(thread_counts);
    EXPECT_EQ(rows[i][1], label[size]) << r.out;
    // A tissue's cells touch on flattened faces: they hold 15-30 % less fluid than free cells.
    const long fluid_here = std::stol(rows[i][2]);
    if (size < 3) EXPECT_EQ(fluid_here, fluid[size]) << r.out;
    else EXPECT_TRUE(fluid_here > 0.7 * fluid[size] && fluid_here < fluid[size]) << r.out;
    EXPECT_EQ(std::stol(rows[i][3]), wall[size]) << r.out;
    EXPECT_DOUBLE_EQ(std::stod(rows[i][4]), dt_ns[size]);
    EXPECT_EQ(std::stoi(rows[i][5]), 1 + static_cast<int>(i) % thread_counts);
    // 400 steps scaled down by the size (802 particles at L1), but never below 100.
    EXPECT_EQ(std::stol(rows[i][6]), std::max(100L, 400 * 802 / (fluid_here + wall[size]))) << r.out;
  }
  for (const char* name : cellsim::kPhaseNames)  // the phase table names every phase
    EXPECT_NE(r.out.find(std::string(name).substr(0, std::string(name).find(" ("))), std::string::npos) << name;
}
