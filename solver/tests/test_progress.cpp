// Progress counts the steps this process runs against those planned, so that percentages and ETA
// stay right when a stage ends early or a run continues with --from.
#include <gtest/gtest.h>

#include <chrono>
#include <regex>
#include <string>
#include <thread>

#include "cli/progress.hpp"
#include "cli_helpers.hpp"

using namespace cellsim;

TEST(Progress, AStageEndingEarlyGivesBackItsStepsAndTheCountReachesTheTotal) {
  Progress p(1000, 1e9, true);
  for (int n = 0; n < 300; ++n) p.step(1e-6, "drying");
  EXPECT_NE(p.line(3e-6, "drying").find("step 300/1000 (30%)"), std::string::npos) << p.line(3e-6, "drying");
  p.unplan(500);  // drying reached steady state 500 steps before its cap
  for (int n = 0; n < 200; ++n) p.step(1e-6, "compression");
  EXPECT_EQ(p.done(), p.planned());
  EXPECT_NE(p.line(5e-6, "compression").find("step 500/500 (100%)"), std::string::npos);
  EXPECT_NE(p.line(5e-6, "compression").find("ETA 0.0 s"), std::string::npos);
}

// The ETA of a number in a line: "... ETA 12.3 s".
double eta_of(const std::string& line) { return std::stod(line.substr(line.rfind("ETA ") + 4)); }

// A compression aimed at strain 0.12 is half-way after 100 of its 10 000 capped steps: the line says
// the strain, and the ETA is the time to the strain (about the 50 ms spent), not to the cap (99 times it).
TEST(Progress, AStageAimedAtAStrainSaysItAndTimesTheRestByIt) {
  const auto run = [](bool aimed) {
    Progress p(10000, 1e9, true);
    if (aimed) p.aim("strain", 0.12);
    for (int n = 0; n <= 100; ++n) {
      p.step(1e-6, "compression", 0.0006 * n);
      if (n % 20 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return p.line(1e-4, "compression");
  };
  const std::string aimed = run(true), capped = run(false);
  EXPECT_NE(aimed.find("(1%), strain 0.0600 of 0.12, t = 100.00 us"), std::string::npos) << aimed;
  EXPECT_EQ(capped.find("strain"), std::string::npos) << capped;
  EXPECT_LT(eta_of(aimed), 0.5) << aimed;   // about 0.05 s
  EXPECT_GT(eta_of(capped), 2.0) << capped;  // about 99 x 0.05 s
  Progress done(10000, 1e9, true);
  done.aim("strain", 0.12);
  done.step(0, "compression", 0.0);
  done.step(0, "compression", 0.13);  // past the goal: nothing left
  EXPECT_EQ(eta_of(done.line(0, "compression")), 0.0) << done.line(0, "compression");
}

TEST(Progress, AContinuedRunCountsItsOwnStepsNeverAboveAHundredPercent) {
  cellsim::testing::ScratchDir dir("progress");
  const auto c = dir.write("case.json", R"({"cell": {"n_wall": 402, "n_fluid": 400},
    "coupling": {"repulsion_f0_N_m": 1.5e-11}, "drying": {"steps": 600},
    "compression": {"steps": 300, "plate_speed_m_s": 10}, "output": {"progress_interval_s": 0}})");
  auto r = cellsim::testing::run_cli({"run", c, "-o", dir.file("dried.h5"), "--set", "compression.steps=0"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = cellsim::testing::run_cli({"run", c, "--from", dir.file("dried.h5"), "-o", dir.file("out.h5")}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::regex progress_line(R"(compression step (\d+)/(\d+) \((\d+)%\).*ETA (-?[0-9.]+) s)");
  int lines = 0;
  for (std::sregex_iterator it(r.err.begin(), r.err.end(), progress_line), end; it != end; ++it, ++lines) {
    EXPECT_EQ(std::stol((*it)[2]), 300) << it->str();  // the compression's steps, not the whole history's
    EXPECT_LE(std::stol((*it)[1]), 300) << it->str();
    EXPECT_LE(std::stol((*it)[3]), 100) << it->str();
    EXPECT_GE(std::stod((*it)[4]), 0.0) << it->str();
  }
  EXPECT_GE(lines, 100) << r.err;
  EXPECT_NE(r.err.find("done, 300 steps"), std::string::npos) << r.err;
}
