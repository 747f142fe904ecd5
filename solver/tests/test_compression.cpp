// The compression stage (model.md §6, §8): strain grows with plate travel after contact; the
// stage stops at end_strain; stresses follow from the plate force.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_helpers.hpp"
#include "io/h5.hpp"

using cellsim::testing::run_cli;
using cellsim::testing::ScratchDir;
namespace h5 = cellsim::h5;

namespace {

// Coarse cells put more turgor on each boundary particle (~ P dx^2): at rest, the paper's LJ
// repulsion cannot hold it and the fluid leaks, so the wall repels 3x harder (as config/ci.yaml).
const char* kSmallFreshCase = R"({
  "cell": {"n_wall": 402, "n_fluid": 400},
  "coupling": {"repulsion_f0_N_m": 1.5e-11},
  "drying": {"dryness": 1.0, "steps": 10000},
  "compression": {"steps": 15000, "plate_speed_m_s": 1},
  "output": {"record_every": 100, "snapshot_every": 5000}
})";

struct Series {
  std::vector<double> stage, strain, plate_strain, force, stress, top_z, bottom_z, height, time;
};

Series read_series(const std::string& path) {
  h5::Handle f = h5::open_file_readonly(path);
  h5::Handle ts = h5::open_group(f.id(), "timeseries");
  return {h5::read_doubles(ts.id(), "stage"), h5::read_doubles(ts.id(), "nominal_strain"),
          h5::read_doubles(ts.id(), "plate_strain"), h5::read_doubles(ts.id(), "plate_force_top_N"),
          h5::read_doubles(ts.id(), "plate_stress_Pa"), h5::read_doubles(ts.id(), "plate_top_z_m"),
          h5::read_doubles(ts.id(), "plate_bottom_z_m"), h5::read_doubles(ts.id(), "cell_height_m"),
          h5::read_doubles(ts.id(), "time_s")};
}

}  // namespace

TEST(Compression, StrainGrowsMonotonicallyWithPlateTravelAfterContact) {
  ScratchDir dir("compression");
  const auto c = dir.write("case.json", kSmallFreshCase);
  const auto r = run_cli({"run", c, "-o", dir.file("out.h5"), "--quiet"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Series s = read_series(dir.file("out.h5"));
  const double speed_m_s = 1.0, range_m = 3e-6, gap_m = 2e-6;  // the case's plate; range and gap: defaults
  int after_contact = 0;
  double previous_strain = -1;
  std::size_t previous = s.stage.size();
  for (std::size_t i = 0; i < s.stage.size(); ++i) {
    if (s.stage[i] != 1.0) {
      EXPECT_TRUE(std::isnan(s.force[i]));  // no plates before compression
      continue;
    }
    if (previous < s.stage.size()) {  // the top plate moves down at the plate speed, the bottom one stays
      EXPECT_NEAR((s.top_z[previous] - s.top_z[i]) / (s.time[i] - s.time[previous]), speed_m_s, 1e-9) << "record " << i;
      EXPECT_EQ(s.bottom_z[i], s.bottom_z[previous]);
    }
    previous = i;
    EXPECT_NEAR(s.stress[i], s.force[i] / (150e-6 * 150e-6), 1e-9 * std::abs(s.stress[i]));
    // The cell lies between the plates, at most their reach (and the start gap) inside them.
    const double plate_gap = s.top_z[i] - s.bottom_z[i];
    EXPECT_LT(s.height[i], plate_gap) << "record " << i;
    EXPECT_LE(plate_gap - s.height[i], 2 * range_m + gap_m + 1e-9) << "record " << i;
    if (s.plate_strain[i] <= 0) continue;  // before first contact
    ++after_contact;
    EXPECT_GT(s.strain[i], previous_strain) << "record " << i;
    EXPECT_GT(s.force[i], 0.0) << "record " << i;
    // The cell's height follows the plate's travel since contact (plate_strain): the growing overlap
    // of plate and wall (Eq 22) takes up a little of it, never more than a fifth at this stiffness.
    EXPECT_LE(s.strain[i], s.plate_strain[i] + 1e-3) << "record " << i;
    EXPECT_GE(s.strain[i], 0.8 * s.plate_strain[i] - 2e-3) << "record " << i;
    previous_strain = s.strain[i];
  }
  EXPECT_GT(after_contact, 100);
  EXPECT_GT(previous_strain, 0.05);  // 15 us at 1 m/s squeezes the 150 um cell by ~8 %
}

TEST(Compression, StopsAtEndStrain) {
  ScratchDir dir("end-strain");
  const auto c = dir.write("case.json", kSmallFreshCase);
  const auto r = run_cli({"run", c, "-o", dir.file("out.h5"), "--set", "compression.end_strain=0.02", "--set", "compression.plate_speed_m_s=5", "--quiet"},
                         dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Series s = read_series(dir.file("out.h5"));
  EXPECT_GE(s.strain.back(), 0.02);
  EXPECT_LT(s.strain.back(), 0.03);  // stopped at once, not at compression.steps
  h5::Handle f = h5::open_file_readonly(dir.file("out.h5"));
  EXPECT_EQ(h5::get_attr_int(f.id(), "completed"), 1);
}
