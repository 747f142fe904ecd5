// The result file: layout, completeness flag, units, determinism (docs/output-reference.md).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "cli_helpers.hpp"
#include "io/h5.hpp"
#include "parallel/threads.hpp"

using cellsim::testing::run_cli;
using cellsim::testing::ScratchDir;
namespace h5 = cellsim::h5;

namespace {

const char* kZeroStepCase = R"({"drying": {"steps": 0}, "compression": {"steps": 0}})";

std::string bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(Output, ZeroStepRunWritesCompleteFileWithGeometryAndMeasures) {
  ScratchDir dir("output");
  const auto c = dir.write("case.json", kZeroStepCase);
  const auto r = run_cli({"run", c, "-o", dir.file("out.h5")}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(std::filesystem::exists(dir.file("out.h5")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.h5.partial")));
  EXPECT_TRUE(std::filesystem::exists(dir.file("out.wall.xdmf")));
  EXPECT_TRUE(std::filesystem::exists(dir.file("out.fluid.xdmf")));

  h5::Handle f = h5::open_file_readonly(dir.file("out.h5"));
  EXPECT_EQ(h5::get_attr_int(f.id(), "completed"), 1);
  EXPECT_FALSE(h5::get_attr_string(f.id(), "git_revision").empty());
  const auto resolved = nlohmann::json::parse(h5::get_attr_string(f.id(), "case_json"));
  EXPECT_EQ(resolved.at("cell").at("n_wall"), 2067);
  EXPECT_TRUE(resolved.at("coupling").at("r0_um").is_number());  // derived values are written resolved

  std::vector<hsize_t> dims;
  h5::read_ints(f.id(), "mesh/triangles", &dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{4130, 3}));
  h5::read_ints(f.id(), "mesh/bonds", &dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{6195, 2}));

  const double R = 75e-6;
  const auto volume = h5::read_doubles(f.id(), "timeseries/volume_m3");
  const auto area = h5::read_doubles(f.id(), "timeseries/area_m2");
  const auto time = h5::read_doubles(f.id(), "timeseries/time_s");
  ASSERT_EQ(volume.size(), 1u);
  EXPECT_EQ(time[0], 0.0);
  EXPECT_NEAR(volume[0] / (4.0 / 3.0 * M_PI * R * R * R), 1.0, 0.01);
  EXPECT_NEAR(area[0] / (4 * M_PI * R * R), 1.0, 0.01);
  h5::Handle ts = h5::open_group(f.id(), "timeseries");
  h5::Handle vol(H5Dopen2(ts.id(), "volume_m3", H5P_DEFAULT), H5Dclose);
  EXPECT_EQ(h5::get_attr_string(vol.id(), "unit"), "m^3");
  EXPECT_TRUE(h5::exists(f.id(), "snapshots/000000000/wall_positions"));
  EXPECT_TRUE(h5::exists(f.id(), "state/fluid_positions"));
}

TEST(Output, SameCaseTwiceGivesIdenticalFiles) {
  // A run that settles, dries, compresses and writes snapshots: every part of the file is exercised.
  ScratchDir dir("determinism");
  const auto c = dir.write("case.json", R"({"cell": {"n_wall": 402, "n_fluid": 400}, "coupling": {"repulsion_f0_N_m": 1.5e-11},
                                            "drying": {"steps": 300}, "compression": {"steps": 300, "plate_speed_m_s": 5},
                                            "output": {"record_every": 50, "snapshot_every": 100}})");
  ASSERT_EQ(run_cli({"run", c, "-o", dir.file("a.h5"), "--quiet"}, dir).exit_code, 0);
  ASSERT_EQ(run_cli({"run", c, "-o", dir.file("b.h5"), "--quiet"}, dir).exit_code, 0);
  {
    h5::Handle f = h5::open_file_readonly(dir.file("a.h5"));
    const auto step = h5::read_doubles(f.id(), "timeseries/step"), stage = h5::read_doubles(f.id(), "timeseries/stage");
    EXPECT_EQ(step.back(), 600.0);  // both stages ran all their steps
    EXPECT_EQ(stage.back(), 1.0);
    EXPECT_GT(h5::get_attr_int(f.id(), "settle_iterations"), 0);
    EXPECT_TRUE(h5::exists(f.id(), "snapshots/000000500"));  // in compression
  }
  const std::string a = bytes(dir.file("a.h5")), b = bytes(dir.file("b.h5"));
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "HDF5 files differ: timestamps or uninitialised data?";
}

TEST(Output, OverridesAreValidatedAndRecorded) {
  ScratchDir dir("override");
  const auto c = dir.write("case.json", kZeroStepCase);
  ASSERT_EQ(run_cli({"run", c, "-o", dir.file("out.h5"), "--set", "drying.dryness=0.5", "--set", "wall.G_MPa=0.18"}, dir)
                .exit_code,
            0);
  h5::Handle f = h5::open_file_readonly(dir.file("out.h5"));
  const auto resolved = nlohmann::json::parse(h5::get_attr_string(f.id(), "case_json"));
  EXPECT_EQ(resolved.at("drying").at("dryness"), 0.5);
  EXPECT_EQ(resolved.at("wall").at("G_MPa"), 0.18);
}

// A choice takes its name as typed or as a JSON string (a script that writes every value as JSON).
TEST(Output, AChoiceOverrideTakesItsNameBareOrQuoted) {
  for (const std::string value : {"pressure", "\"pressure\""}) {
    ScratchDir dir("choice");
    const auto c = dir.write("case.json", kZeroStepCase);
    ASSERT_EQ(run_cli({"run", c, "-o", dir.file("out.h5"), "--set", "coupling.model=" + value}, dir).exit_code, 0)
        << value;
    h5::Handle f = h5::open_file_readonly(dir.file("out.h5"));
    const auto resolved = nlohmann::json::parse(h5::get_attr_string(f.id(), "case_json"));
    EXPECT_EQ(resolved.at("coupling").at("model"), "pressure") << value;
    EXPECT_EQ(resolved.at("drying").at("steady_rms_speed_m_s"), 0.05) << value;  // derived from the coupling
  }
}

TEST(Output, TwoThreadsTwiceGiveIdenticalFilesThatAgreeWithOneThreadToRoundOff) {
  if (!cellsim::built_with_openmp()) GTEST_SKIP() << "built without OpenMP: only one thread";
  ScratchDir dir("threads");
  const auto c = dir.write("case.json", R"({"cell": {"n_wall": 402, "n_fluid": 400}, "drying": {"steps": 400}, "coupling": {"repulsion_f0_N_m": 1.5e-11},
                                            "compression": {"steps": 0}, "output": {"record_every": 100}})");
  for (const char* name : {"two_a.h5", "two_b.h5"})
    ASSERT_EQ(run_cli({"run", c, "-o", dir.file(name), "--threads", "2", "--quiet"}, dir).exit_code, 0);
  ASSERT_EQ(run_cli({"run", c, "-o", dir.file("one.h5"), "--quiet"}, dir).exit_code, 0);
  EXPECT_TRUE(bytes(dir.file("two_a.h5")) == bytes(dir.file("two_b.h5")));
  h5::Handle two = h5::open_file_readonly(dir.file("two_a.h5")), one = h5::open_file_readonly(dir.file("one.h5"));
  EXPECT_EQ(h5::get_attr_int(two.id(), "threads"), 2);
  EXPECT_EQ(h5::get_attr_int(one.id(), "threads"), 1);
  const auto p2 = h5::read_doubles(two.id(), "timeseries/mean_pressure_Pa"),
             p1 = h5::read_doubles(one.id(), "timeseries/mean_pressure_Pa");
  ASSERT_EQ(p1.size(), p2.size());
  ASSERT_GE(p1.size(), 5u);
  for (std::size_t k = 0; k < p1.size(); ++k) EXPECT_NEAR(p2[k], p1[k], 1e-6 * std::abs(p1.back())) << k;
}
