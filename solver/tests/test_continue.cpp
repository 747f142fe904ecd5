// Compression continued from a dried state (--from) equals one uninterrupted run, bit for bit;
// a state dried with other parameters is refused.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "cli_helpers.hpp"
#include "h5.hpp"

using cellsim::testing::run_cli;
using cellsim::testing::ScratchDir;
namespace h5 = cellsim::h5;

namespace {

// A reduced cell: seconds, not minutes. 10 m/s so the plate reaches the cell quickly.
// Coarse cells put more turgor on each boundary particle (~ P dx^2): at rest, the paper's LJ
// repulsion cannot hold it and the fluid leaks, so the wall repels 3x harder (as config/ci.yaml).
const char* kSmallCase = R"({
  "cell": {"n_wall": 402, "n_fluid": 400},
  "coupling": {"repulsion_f0_N_m": 1.5e-11},
  "drying": {"dryness": 0.5, "steps": 20000, "ramp_time_us": 8, "Lp_m_per_s_Pa": 2.5e-5},
  "compression": {"steps": 1500, "plate_speed_m_s": 10},
  "output": {"record_every": 50, "snapshot_every": 0}
})";

std::vector<double> dataset(const std::string& file, const std::string& name) {
  h5::Handle f = h5::open_file_readonly(file);
  return h5::read_doubles(f.id(), name);
}

}  // namespace

TEST(Continue, FromDriedStateIsBitIdenticalToOneRun) {
  ScratchDir dir("continue");
  const auto c = dir.write("case.json", kSmallCase);
  auto r = run_cli({"run", c, "-o", dir.file("whole.h5"), "--quiet"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_cli({"run", c, "-o", dir.file("dried.h5"), "--set", "compression.steps=0", "--quiet"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_cli({"run", c, "--from", dir.file("dried.h5"), "-o", dir.file("continued.h5"), "--quiet"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;

  for (const char* name : {"timeseries/time_s", "timeseries/plate_force_top_N", "timeseries/nominal_strain",
                           "timeseries/volume_m3", "timeseries/fluid_mass_kg", "state/wall_positions",
                           "state/fluid_positions", "state/fluid_velocities", "state/fluid_density"}) {
    const auto a = dataset(dir.file("whole.h5"), name), b = dataset(dir.file("continued.h5"), name);
    ASSERT_EQ(a.size(), b.size()) << name;
    ASSERT_FALSE(a.empty()) << name;
    // Bytes, not values: NaN plate forces before compression must match too.
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0)
        << name << " differs between one run and --from";
  }
  const auto stage = dataset(dir.file("continued.h5"), "timeseries/stage");
  EXPECT_EQ(stage.front(), 0.0);  // the drying history is carried over
  EXPECT_EQ(stage.back(), 1.0);
  const auto force = dataset(dir.file("continued.h5"), "timeseries/plate_force_top_N");
  EXPECT_GT(force.back(), 0.0);  // the plate reached the cell
}

TEST(Continue, RefusesAStateDriedWithOtherParameters) {
  ScratchDir dir("continue-mismatch");
  const auto c = dir.write("case.json", kSmallCase);
  ASSERT_EQ(run_cli({"run", c, "-o", dir.file("dried.h5"), "--set", "compression.steps=0", "--set", "drying.steps=200", "--quiet"}, dir)
                .exit_code,
            0);
  auto r = run_cli({"run", c, "--from", dir.file("dried.h5"), "-o", dir.file("out.h5"), "--set", "drying.steps=200", "--set", "drying.dryness=0.9"},
                   dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("drying.dryness"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.h5")));
  // Plate settings may differ: that is the point of continuing.
  r = run_cli({"run", c, "--from", dir.file("dried.h5"), "-o", dir.file("out.h5"), "--set", "drying.steps=200", "--set", "compression.plate_speed_m_s=5", "--set", "compression.steps=10", "--quiet"},
              dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // A file that is not a result is refused with a message naming it.
  const auto junk = dir.write("junk.h5", "not hdf5");
  r = run_cli({"run", c, "--from", junk, "-o", dir.file("out2.h5")}, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("junk.h5"), std::string::npos) << r.err;
}
