// A run continued from a saved state (--from) equals one uninterrupted run, bit for bit: compression
// from a dried state, and drying from a state at rest settled at another dryness; a state saved with
// other parameters is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "cli_helpers.hpp"
#include "io/h5.hpp"
#include "parallel/threads.hpp"

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

// Runs case_json whole, then saved with `save` (by default: dried) and continued with --from; the named
// datasets must match byte for byte. Returns the scratch directory's continued result.
std::string expect_continued_run_equals_one_run(ScratchDir& dir, const char* case_json,
                                                const std::vector<std::string>& names,
                                                const std::vector<std::string>& save = {"--set", "compression.steps=0"}) {
  const auto c = dir.write("case.json", case_json);
  std::vector<std::string> save_run{"run", c, "-o", dir.file("dried.h5"), "--quiet"};
  save_run.insert(save_run.end(), save.begin(), save.end());
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"run", c, "-o", dir.file("whole.h5"), "--quiet"}, save_run,
        {"run", c, "--from", dir.file("dried.h5"), "-o", dir.file("continued.h5"), "--quiet"}}) {
    const auto r = run_cli(args, dir);
    if (r.exit_code != 0) {
      ADD_FAILURE() << "exit " << r.exit_code << ": " << r.err;
      return {};
    }
  }
  for (const auto& name : names) {
    const auto a = dataset(dir.file("whole.h5"), name), b = dataset(dir.file("continued.h5"), name);
    EXPECT_EQ(a.size(), b.size()) << name;
    EXPECT_FALSE(a.empty()) << name;
    // Bytes, not values: NaN plate forces before compression must match too.
    if (a.size() == b.size())
      EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0)
          << name << " differs between one run and --from";
  }
  return dir.file("continued.h5");
}

TEST(Continue, FromDriedStateIsBitIdenticalToOneRun) {
  ScratchDir dir("continue");
  const auto continued = expect_continued_run_equals_one_run(
      dir, kSmallCase,
      {"timeseries/time_s", "timeseries/plate_force_top_N", "timeseries/nominal_strain", "timeseries/volume_m3",
       "timeseries/fluid_mass_kg", "state/wall_positions", "state/fluid_positions", "state/fluid_velocities",
       "state/fluid_density"});
  if (continued.empty()) return;
  const auto stage = dataset(continued, "timeseries/stage");
  EXPECT_EQ(stage.front(), 0.0);  // the drying history is carried over
  EXPECT_EQ(stage.back(), 1.0);
  const auto force = dataset(continued, "timeseries/plate_force_top_N");
  EXPECT_GT(force.back(), 0.0);  // the plate reached the cell
}

// The workflow settles once per cell and dries it to every dryness from there: a state at rest
// (drying.steps = 0) settled at X/X0 = 1 gives the same half-dried and compressed cell, and the
// same settle report, as one run at X/X0 = 0.5.
TEST(Continue, DryingFromAStateAtRestIsBitIdenticalToOneRun) {
  ScratchDir dir("continue-rest");
  const auto continued = expect_continued_run_equals_one_run(
      dir, kSmallCase,
      {"timeseries/time_s", "timeseries/mean_pressure_Pa", "timeseries/volume_m3", "timeseries/fluid_mass_kg",
       "timeseries/plate_force_top_N", "state/wall_positions", "state/fluid_positions", "state/fluid_mass"},
      {"--set", "drying.dryness=1", "--set", "drying.steps=0", "--set", "compression.steps=0"});
  if (continued.empty()) return;
  const auto volume = dataset(continued, "timeseries/volume_m3");
  ASSERT_GT(volume.size(), 2u);
  EXPECT_LT(volume.back(), 0.9 * volume.front());  // it did dry (to X/X0 = 0.5), from the state at rest
  h5::Handle whole = h5::open_file_readonly(dir.file("whole.h5")), cont = h5::open_file_readonly(continued);
  EXPECT_GT(h5::get_attr_int(cont.id(), "settle_iterations"), 0);
  EXPECT_EQ(h5::get_attr_int(whole.id(), "settle_iterations"), h5::get_attr_int(cont.id(), "settle_iterations"));
  for (const char* attribute : {"settle_residual", "settle_mass_ratio", "settle_volume_ratio"})
    EXPECT_EQ(h5::get_attr_double(whole.id(), attribute), h5::get_attr_double(cont.id(), attribute)) << attribute;
}

// A state at rest may differ from the case in the dryness and the drying's length only. A cell only
// settled has not dried, so it has no drying cap to have hit: no warning.
TEST(Continue, RefusesAStateAtRestSettledWithOtherParameters) {
  ScratchDir dir("continue-rest-mismatch");
  const auto c = dir.write("case.json", kSmallCase);
  const auto settled =
      run_cli({"run", c, "-o", dir.file("rest.h5"), "--set", "drying.steps=0", "--set", "compression.steps=0", "--quiet"}, dir);
  ASSERT_EQ(settled.exit_code, 0) << settled.err;
  EXPECT_EQ(settled.err.find("WARNING"), std::string::npos) << settled.err;
  EXPECT_EQ(h5::get_attr_string(h5::open_file_readonly(dir.file("rest.h5")).id(), "warning"), "");
  const auto r = run_cli({"run", c, "--from", dir.file("rest.h5"), "-o", dir.file("out.h5"), "--set", "cell.turgor_kPa=300"}, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("settled with cell.turgor_kPa"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.h5")));
}

// A state continued on another thread count gives round-off, not the same bits: the run says so.
TEST(Continue, SaysWhenTheSavedRunRanOnAnotherThreadCount) {
  if (!cellsim::built_with_openmp()) GTEST_SKIP() << "built without OpenMP: one thread only";
  ScratchDir dir("continue-threads");
  const auto c = dir.write("case.json", kSmallCase);
  const auto settled = run_cli(
      {"run", c, "-o", dir.file("rest.h5"), "--set", "drying.steps=0", "--set", "compression.steps=0", "--quiet"}, dir);
  ASSERT_EQ(settled.exit_code, 0) << settled.err;
  const std::vector<std::string> dry{"run", c, "--from", dir.file("rest.h5"), "--set", "drying.steps=20",
                                     "--set", "compression.steps=0", "--quiet", "-o"};
  auto same = dry, other = dry;
  same.insert(same.end(), {dir.file("same.h5"), "--threads", "1"});
  other.insert(other.end(), {dir.file("other.h5"), "--threads", "2"});
  const auto r_same = run_cli(same, dir), r_other = run_cli(other, dir);
  ASSERT_EQ(r_same.exit_code, 0) << r_same.err;
  EXPECT_EQ(r_same.err.find("note:"), std::string::npos) << r_same.err;
  ASSERT_EQ(r_other.exit_code, 0) << r_other.err;
  EXPECT_NE(r_other.err.find("ran on 1 thread(s) and this run on 2"), std::string::npos) << r_other.err;
}

// Two bonded cells (of the reduced tissue's 642 wall particles: 402 are too few to keep a faceted
// cell's fluid in), half dried: their lamella bonds carry damage (the largest opening so far) into
// compression, so --from must restore it as well as which bonds still hold.
TEST(Continue, ATissueCarriesItsLamellaDamageAcrossTheDriedState) {
  ScratchDir dir("continue-tissue");
  const char* two_cells = R"({
    "cell": {"n_wall": 642, "n_fluid": 700},
    "tissue": {"cells_x": 2},
    "coupling": {"repulsion_f0_N_m": 1.5e-11},
    "drying": {"dryness": 0.5, "steps": 20000, "ramp_time_us": 8, "Lp_m_per_s_Pa": 2.5e-5},
    "compression": {"steps": 800, "plate_speed_m_s": 10, "plate_length_um": 400, "plate_width_um": 400},
    "output": {"record_every": 50, "snapshot_every": 0}
  })";
  const auto continued = expect_continued_run_equals_one_run(
      dir, two_cells,
      {"timeseries/time_s", "timeseries/plate_force_top_N", "timeseries/lamella_intact", "timeseries/volume_m3",
       "state/wall_positions", "state/fluid_positions", "state/lamella_peak_opening"});
  if (continued.empty()) return;
  const auto peak = dataset(dir.file("dried.h5"), "state/lamella_peak_opening");
  ASSERT_FALSE(peak.empty());
  EXPECT_GT(*std::max_element(peak.begin(), peak.end()), 51e-9 / 2);  // drying opened some bond toward its peak
}

// A periodic slab (2 x 2 cells to the period, one layer) continued into compression from its dried
// state: the period shrank as it dried, and the continued run must list its walls' contacts across
// that period, not the one the case builds (model.md §10b), to compress bit for bit as one run does.
// 4000 compression steps: in 1500, no wall pair across the period came within the gap, and the run
// matched even with the built period in the lists.
TEST(Continue, APeriodicSlabCarriesItsShrunkenPeriodAcrossTheDriedState) {
  ScratchDir dir("continue-slab");
  const char* slab = R"({
    "cell": {"n_wall": 642, "n_fluid": 700},
    "tissue": {"cells_x": 2, "cells_y": 2, "lateral": "periodic"},
    "coupling": {"repulsion_f0_N_m": 1.5e-11},
    "drying": {"dryness": 0.5, "steps": 6000, "ramp_time_us": 4, "Lp_m_per_s_Pa": 2.5e-5},
    "compression": {"steps": 4000, "plate_speed_m_s": 10},
    "output": {"record_every": 50, "snapshot_every": 0}
  })";
  const auto continued = expect_continued_run_equals_one_run(
      dir, slab,
      {"timeseries/time_s", "timeseries/plate_force_top_N", "timeseries/lateral_stress_Pa",
       "timeseries/period_x_m", "state/wall_positions", "state/fluid_positions"});
  if (continued.empty()) return;
  const auto period = dataset(dir.file("dried.h5"), "timeseries/period_x_m");
  ASSERT_FALSE(period.empty());
  EXPECT_LT(period.back(), 0.95 * period.front());  // it shrank by far more than the lists' skin
  const auto force = dataset(continued, "timeseries/plate_force_top_N");
  EXPECT_GT(force.back(), 0.0);  // the plates pressed the slab
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

// A wall that yields while it dries carries its plastic set (the bonds' rest lengths) and the energy the
// flow dissipated across the dried state: compression and unloading continue bit for bit.
TEST(Continue, APlasticWallCarriesItsSetAcrossTheDriedState) {
  ScratchDir dir("continue_plastic");
  const auto continued = expect_continued_run_equals_one_run(
      dir, R"({"cell": {"n_wall": 162, "n_fluid": 120, "diameter_um": 40}, "time": {"dt_ns": 0.5},
               "drying": {"dryness": 0.5, "steps": 3000, "ramp_time_us": 1},
               "wall": {"yield_stress_MPa": 0.3, "hardening_MPa": 20},
               "compression": {"plate_speed_m_s": 5, "unload_at_strain": 0.05, "gap_um": 0.5},
               "output": {"record_every": 50, "snapshot_every": 0}})",
      {"timeseries/plastic_loss_J", "timeseries/wall_plastic_strain_mean", "timeseries/plate_force_top_N",
       "timeseries/energy_residual_J", "state/bond_plastic_elongation", "state/wall_positions"});
  if (continued.empty()) return;
  const auto loss = dataset(continued, "timeseries/plastic_loss_J");
  const auto stage = dataset(continued, "timeseries/stage");
  std::size_t first_compression = 0;
  while (stage[first_compression] == 0.0) ++first_compression;
  EXPECT_GT(loss[first_compression], 0.0);  // the wall yielded while it dried: the set the state carries
  EXPECT_GT(loss.back(), loss[first_compression]);  // and again under the plates
}
