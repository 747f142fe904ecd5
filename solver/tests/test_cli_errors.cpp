// Each class of bad input gives a one-line message naming the problem, exit code 2, and nothing
// under the output's name (issue: solver foundation, item 4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "cli_helpers.hpp"

using cellsim::testing::run_cli;
using cellsim::testing::ScratchDir;

namespace {

const char* kTinyCase = R"({"cell": {"n_wall": 162, "n_fluid": 100}, "drying": {"steps": 0}, "compression": {"steps": 0}})";

void expect_input_error(const cellsim::testing::Args& args, const ScratchDir& dir, const std::vector<std::string>& mentions) {
  const auto r = run_cli(args, dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  for (const auto& m : mentions) EXPECT_NE(r.err.find(m), std::string::npos) << "stderr lacks '" << m << "': " << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.h5")));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "expected one line: " << r.err;
}

}  // namespace

TEST(CliErrors, MalformedJson) {
  ScratchDir dir("malformed");
  const auto c = dir.write("case.json", R"({"cell": {"n_wall": 162,}})");
  expect_input_error({"run", c, "-o", dir.file("out.h5")}, dir, {"not valid JSON", "case.json"});
}

// The JSON library stops at a NUL byte: a case followed by one (and anything after it) was read as the
// case before it, the rest ignored (found by fuzzing: a NUL appended to a valid case was accepted).
TEST(CliErrors, ANulByteInTheCaseFileIsRefused) {
  ScratchDir dir("nul");
  const std::string nul(1, '\0');
  for (const std::string& tail : {nul, nul + R"({"drying": {"dryness": 0.5}})"}) {
    const auto c = dir.write("case.json", R"({"cell": {"n_wall": 162}})" + tail);
    expect_input_error({"validate", c}, dir, {"not valid JSON", "NUL byte at offset 25", "case.json"});
    expect_input_error({"run", c, "-o", dir.file("out.h5")}, dir, {"NUL byte at offset 25"});
  }
  const auto in_a_string = dir.write("case.json", std::string(R"({"cell": {"n_wa)") + '\0' + R"(ll": 162}})");
  expect_input_error({"validate", in_a_string}, dir, {"NUL byte at offset 15"});
}

TEST(CliErrors, UnknownKeySuggestsNearest) {
  ScratchDir dir("unknown");
  const auto c = dir.write("case.json", R"({"wall": {"G_Mpa": 18}})");
  expect_input_error({"run", c, "-o", dir.file("out.h5")}, dir, {"unknown key 'wall.G_Mpa'", "wall.G_MPa"});
}

TEST(CliErrors, UnknownSectionSuggestsNearest) {
  ScratchDir dir("section");
  const auto c = dir.write("case.json", R"({"dryng": {"dryness": 0.5}})");
  expect_input_error({"validate", c}, dir, {"unknown key 'dryng.dryness'", "drying.dryness"});
}

TEST(CliErrors, WrongType) {
  ScratchDir dir("type");
  const auto c = dir.write("case.json", R"({"cell": {"turgor_kPa": "200"}})");
  expect_input_error({"run", c, "-o", dir.file("out.h5")}, dir, {"cell.turgor_kPa", "\"200\"", "expected a number"});
}

TEST(CliErrors, NonIntegerCount) {
  ScratchDir dir("integer");
  const auto c = dir.write("case.json", R"({"cell": {"n_wall": 2067.5}})");
  expect_input_error({"validate", c}, dir, {"cell.n_wall", "2067.5", "integer"});
}

TEST(CliErrors, NonFiniteValueInFile) {
  ScratchDir dir("nonfinite");
  const auto c = dir.write("case.json", R"({"wall": {"G_MPa": 1e999}})");
  expect_input_error({"run", c, "-o", dir.file("out.h5")}, dir, {"wall.G_MPa", "finite"});
}

TEST(CliErrors, NonFiniteValueInOverride) {
  ScratchDir dir("nonfinite-set");
  const auto c = dir.write("case.json", kTinyCase);
  expect_input_error({"run", c, "-o", dir.file("out.h5"), "--set", "drying.dryness=nan"}, dir,
                     {"drying.dryness", "nan", "finite"});
}

TEST(CliErrors, OutOfRange) {
  ScratchDir dir("range");
  const auto c = dir.write("case.json", kTinyCase);
  expect_input_error({"run", c, "-o", dir.file("out.h5"), "--set", "drying.dryness=1.5"}, dir,
                     {"drying.dryness = 1.5", "0 < value <= 1"});
}

TEST(CliErrors, OverrideOfUnknownKey) {
  ScratchDir dir("set-unknown");
  const auto c = dir.write("case.json", kTinyCase);
  expect_input_error({"validate", c, "--set", "drying.drynes=0.5"}, dir, {"drying.drynes", "drying.dryness"});
}

TEST(CliErrors, MissingCaseFile) {
  ScratchDir dir("missing");
  expect_input_error({"run", dir.file("nope.json"), "-o", dir.file("out.h5")}, dir, {"nope.json", "cannot open"});
}

TEST(CliErrors, UnwritableOutput) {
  ScratchDir dir("unwritable");
  const auto c = dir.write("case.json", kTinyCase);
  const auto r = run_cli({"run", c, "-o", dir.file("no/such/dir/out.h5")}, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no/such/dir"), std::string::npos) << r.err;
}

TEST(CliErrors, ImpossibleGeometry) {
  ScratchDir dir("geometry");
  const auto c = dir.write("case.json", R"({"cell": {"fill_gap_um": 80}})");
  expect_input_error({"run", c, "-o", dir.file("out.h5")}, dir, {"cell.fill_gap_um", "radius"});
}

TEST(CliErrors, UsageErrors) {
  ScratchDir dir("usage");
  EXPECT_EQ(run_cli({}, dir).exit_code, 2);
  EXPECT_EQ(run_cli({"frobnicate"}, dir).exit_code, 2);
  const auto c = dir.write("case.json", kTinyCase);
  const auto r = run_cli({"run", c}, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("-o OUT.h5"), std::string::npos) << r.err;
}

TEST(Cli, HelpAndVersionSucceed) {
  ScratchDir dir("help");
  const auto help = run_cli({"--help"}, dir);
  EXPECT_EQ(help.exit_code, 0);
  // Every exit code errors.hpp defines is named in the help, with its meaning.
  for (const char* code : {"0 success", "2 bad input", "3 numerical failure", "4 file error"})
    EXPECT_NE(help.out.find(code), std::string::npos) << code << " missing from:\n" << help.out;
  EXPECT_EQ(run_cli({"--version"}, dir).exit_code, 0);
  for (const char* command : {"run", "bench", "validate"}) {  // help after a command: usage, no run
    const auto r = run_cli({command, "--help"}, dir);
    EXPECT_EQ(r.exit_code, 0) << command << ": " << r.err;
    EXPECT_NE(r.out.find("usage:"), std::string::npos) << command;
  }
}

TEST(CliErrors, ThreadCountOutOfRange) {
  ScratchDir dir("threads");
  const auto c = dir.write("case.json", kTinyCase);
  expect_input_error({"run", c, "-o", dir.file("out.h5"), "--threads", "0"}, dir, {"--threads", "positive integer"});
  expect_input_error({"run", c, "-o", dir.file("out.h5"), "--threads", "100000"}, dir,
                     {"--threads = 100000", "between 1 and"});
  expect_input_error({"run", c, "-o", dir.file("out.h5"), "--threads", "two"}, dir, {"--threads", "'two'"});
}

// The quasi-static scheme needs a fluid with an equilibrium of its own.
TEST(CliErrors, QuasiStaticNeedsTheClosedCellFluid) {
  ScratchDir dir("quasi static sph");
  const auto c = dir.write("case.json", R"({"time": {"scheme": "quasi_static"}})");
  expect_input_error({"run", c, "-o", dir.file("out.h5")}, dir, {"time.scheme = quasi_static", "fluid.model = cavity"});
}

// A closed cell given SPH-only keys away from their defaults runs, with one warning naming them.
TEST(CliErrors, AClosedCellWarnsOfTheSphKeysItIgnores) {
  ScratchDir dir("cavity ignores");
  const auto c = dir.write("case.json", R"({"fluid": {"model": "cavity", "viscosity_Pa_s": 0.5},
      "cell": {"n_wall": 162, "n_fluid": 100, "diameter_um": 40}, "coupling": {"model": "pressure"},
      "drying": {"steps": 0}, "compression": {"steps": 0}, "time": {"dt_ns": 0.5}})");
  const auto r = run_cli({"validate", c}, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* key : {"WARNING", "cell.n_fluid", "fluid.viscosity_Pa_s", "coupling.model"})
    EXPECT_NE(r.err.find(key), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("cell.n_wall"), std::string::npos) << r.err;
}

// Two resolved cases alike: the same keys and texts, numbers within 1e-12 (validate prints 15 digits, so
// a value derived from a printed one may move in its last).
namespace {
bool same_case(const nlohmann::json& a, const nlohmann::json& b) {
  if (a.is_object()) {
    if (!b.is_object() || a.size() != b.size()) return false;
    for (const auto& [key, value] : a.items())
      if (!b.contains(key) || !same_case(value, b[key])) return false;
    return true;
  }
  if (a.is_number() && b.is_number())
    return std::abs(a.get<double>() - b.get<double>()) <= 1e-12 * std::max(std::abs(a.get<double>()), std::abs(b.get<double>()));
  return a == b;
}
}  // namespace

// The case `validate` prints, every derived key filled in, reads back without a warning: a key the
// case ignores is warned only where its value differs from the one the case takes without it. (A
// dynamic cell's resolved compression.cell_rotation = free was warned as ignored.)
TEST(CliErrors, AResolvedCaseReadsBackWithoutAWarning) {
  ScratchDir dir("resolved");
  const std::vector<std::string> cases = {
      R"({"cell": {"n_wall": 162, "n_fluid": 100}, "time": {"dt_ns": 0.5}})",
      R"({"cell": {"n_wall": 162, "n_fluid": 100}, "time": {"dt_ns": 0.5}, "fluid": {"h_over_dx": 1.2},
          "coupling": {"model": "pressure"}})",
      R"({"cell": {"n_wall": 162, "diameter_um": 40}, "fluid": {"model": "cavity"}, "time": {"dt_ns": 0.5}})",
      R"({"cell": {"n_wall": 162, "diameter_um": 40}, "fluid": {"model": "cavity"}, "time": {"scheme": "quasi_static"}})",
      R"({"cell": {"n_wall": 162, "diameter_um": 40}, "fluid": {"model": "cavity"}, "time": {"scheme": "quasi_static"},
          "tissue": {"cells_x": 2, "cells_y": 2, "lateral": "periodic"}})"};
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto first = run_cli({"validate", dir.write("case" + std::to_string(k) + ".json", cases[k])}, dir);
    ASSERT_EQ(first.exit_code, 0) << first.err;
    EXPECT_EQ(first.err.find("WARNING"), std::string::npos) << cases[k] << ": " << first.err;
    const auto again = run_cli({"validate", dir.write("resolved" + std::to_string(k) + ".json", first.out)}, dir);
    EXPECT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.err.find("WARNING"), std::string::npos) << cases[k] << ": " << again.err;
    EXPECT_TRUE(same_case(nlohmann::json::parse(again.out), nlohmann::json::parse(first.out))) << again.out;
  }
}

// h0 and h0/dx both given: the same smoothing length is taken (above), two different ones are refused.
TEST(CliErrors, TwoDifferentSmoothingLengthsAreRefused) {
  ScratchDir dir("two h");
  const auto c = dir.write("case.json", R"({"cell": {"n_wall": 162, "n_fluid": 100}, "time": {"dt_ns": 0.5},
      "fluid": {"h0_um": 5.0, "h_over_dx": 1.2}})");
  expect_input_error({"validate", c}, dir, {"fluid.h0_um = 5", "fluid.h_over_dx = 1.2", "differ"});
}

// An h0 in um is checked as the h0/dx it makes on the cell's lattice (found by the fuzzer's round trip:
// h0 = 0.5 um was taken, printed with h0/dx = 0.023, and that printed case refused).
TEST(CliErrors, AnH0ThatMakesH0OverDxOutOfItsRangeIsRefused) {
  ScratchDir dir("h0 range");
  const auto c = dir.write("case.json", R"({"cell": {"n_wall": 162, "n_fluid": 100}, "time": {"dt_ns": 0.5},
      "fluid": {"h0_um": 0.5}})");
  expect_input_error({"validate", c}, dir, {"fluid.h0_um = 0.5", "h0/dx = 0.02", "fluid.h_over_dx's range"});
}

// Two more the round trip found: a length so small that it is 0 in metres passed "> 0"; a wall of
// thickness 0 derived a wall gap of 0, out of that key's range. Each is refused, naming its key.
TEST(CliErrors, ALengthThatUnderflowsAndAGapDerivedAsZeroAreRefused) {
  ScratchDir dir("underflow");
  const auto tiny = dir.write("tiny.json", R"({"cell": {"n_wall": 162, "n_fluid": 100}, "time": {"dt_ns": 0.5},
      "compression": {"plate_width_um": 5e-324}})");
  expect_input_error({"validate", tiny}, dir, {"compression.plate_width_um", "too small to hold in SI units"});
  const auto thin = dir.write("thin.json", R"({"cell": {"n_wall": 162, "n_fluid": 100}, "time": {"dt_ns": 0.5},
      "wall": {"thickness_um": 0}})");
  expect_input_error({"validate", thin}, dir, {"tissue.wall_gap_um", "wall.thickness_um = 0"});
  const auto gap = dir.write("gap.json", R"({"cell": {"n_wall": 162, "n_fluid": 100}, "time": {"dt_ns": 0.5},
      "wall": {"thickness_um": 0}, "tissue": {"wall_gap_um": 6}})");
  EXPECT_EQ(run_cli({"validate", gap}, dir).exit_code, 0);
}

// A relaxation that does not reach equilibrium within its cap stops the run (exit 3), naming the step
// and the keys, and leaves only a partial file.
TEST(CliErrors, ARelaxationOverItsCapStopsTheRun) {
  ScratchDir dir("relaxation cap");
  const auto c = dir.write("case.json", R"({"fluid": {"model": "cavity"}, "cell": {"n_wall": 162, "diameter_um": 40},
      "time": {"scheme": "quasi_static", "dt_ns": 500, "relaxation_max_iterations": 3},
      "drying": {"dryness": 0.5, "steps": 10}, "compression": {"steps": 0}})");
  const auto r = run_cli({"run", c, "-o", dir.file("out.h5"), "--quiet"}, dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  for (const char* m : {"did not reach equilibrium", "time.relaxation_max_iterations = 3", "step 1"})
    EXPECT_NE(r.err.find(m), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.h5")));
}
