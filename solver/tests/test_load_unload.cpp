// Load-unload (compression.unload_at_strain, docs/model.md §6): the top plate turns at the unload strain,
// moves back up at the unload speed, and the stage ends when the cell leaves it; the strain then is the
// permanent set, larger for a wall that yields (wall.yield_stress_MPa) than for the elastic wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cli_helpers.hpp"
#include "io/h5.hpp"

using cellsim::testing::run_cli;
using cellsim::testing::ScratchDir;
namespace h5 = cellsim::h5;

namespace {

// The tests' small cell (small_cell.hpp), settled and not dried, loaded to strain 0.1 at 2 m/s and
// unloaded at 1 m/s. wall_extra: the wall's keys.
std::string small_cell_load_unload(const std::string& wall_extra) {
  return R"({"cell": {"n_wall": 162, "n_fluid": 120, "diameter_um": 40}, "time": {"dt_ns": 0.5},
             "drying": {"steps": 2000},
             "compression": {"plate_speed_m_s": 2, "unload_at_strain": 0.1, "unload_speed_m_s": 1, "gap_um": 0.5},
             "wall": {)" + wall_extra + R"(},
             "output": {"record_every": 20, "snapshot_every": 0}})";
}

struct Loop {
  std::vector<double> time, strain, force, top_z, plastic_loss, residual, plate_work;
  double peak_strain() const { return *std::max_element(strain.begin(), strain.end()); }
};

Loop run_loop(const ScratchDir& dir, const std::string& name, const std::string& wall_extra) {
  const auto c = dir.write(name + ".json", small_cell_load_unload(wall_extra));
  const auto r = run_cli({"run", c, "-o", dir.file(name + ".h5"), "--quiet"}, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  h5::Handle f = h5::open_file_readonly(dir.file(name + ".h5"));
  h5::Handle ts = h5::open_group(f.id(), "timeseries");
  const auto stage = h5::read_doubles(ts.id(), "stage");
  Loop loop;
  const auto keep = [&](const char* quantity, std::vector<double>& into) {
    const auto all = h5::read_doubles(ts.id(), quantity);
    for (std::size_t i = 0; i < all.size(); ++i)
      if (stage[i] == 1.0) into.push_back(all[i]);
  };
  keep("time_s", loop.time);
  keep("nominal_strain", loop.strain);
  keep("plate_force_top_N", loop.force);
  keep("plate_top_z_m", loop.top_z);
  keep("plastic_loss_J", loop.plastic_loss);
  keep("energy_residual_J", loop.residual);
  keep("plate_work_J", loop.plate_work);
  return loop;
}

}  // namespace

TEST(LoadUnload, ThePlateTurnsAtTheUnloadStrainAndTheStageEndsWhenTheCellLeavesIt) {
  ScratchDir dir("load_unload");
  const Loop loop = run_loop(dir, "elastic", "");
  ASSERT_GT(loop.time.size(), 20u);
  // Down at 2 m/s until the turn, up at 1 m/s after it: the turn is the top plate's lowest point.
  const auto turn = static_cast<std::size_t>(std::min_element(loop.top_z.begin(), loop.top_z.end()) - loop.top_z.begin());
  ASSERT_GT(turn, 1u);
  ASSERT_LT(turn + 2, loop.time.size());
  EXPECT_NEAR((loop.top_z[turn - 2] - loop.top_z[turn - 1]) / (loop.time[turn - 1] - loop.time[turn - 2]), 2.0, 1e-6);
  EXPECT_NEAR((loop.top_z[turn + 2] - loop.top_z[turn + 1]) / (loop.time[turn + 2] - loop.time[turn + 1]), 1.0, 1e-6);
  EXPECT_GE(loop.peak_strain(), 0.1);
  EXPECT_LT(loop.peak_strain(), 0.1 + 2.0 * 20 * 0.5e-9 / 40e-6 + 0.01);  // it turned within a record of 0.1
  // The run ends on the way back up, when the cell no longer touches the top plate.
  EXPECT_EQ(loop.force.back(), 0.0);
  EXPECT_GT(loop.force[turn], 0.0);
  EXPECT_LT(loop.strain.back(), loop.peak_strain());
  // An elastic wall dissipates nothing of its own; the account holds over the loop.
  EXPECT_EQ(loop.plastic_loss.back(), 0.0);
  EXPECT_LT(std::abs(loop.residual.back() - loop.residual.front()), 0.05 * std::abs(loop.plate_work.back()) + 1e-15);
}

TEST(LoadUnload, AWallThatYieldsKeepsALargerPermanentSetAndItsLossIsInTheAccount) {
  ScratchDir dir("load_unload_plastic");
  const Loop elastic = run_loop(dir, "elastic", "");
  // A yield stress the settled cell's wall (the turgor's pR/2t = 0.33 MPa here, more on its most
  // stretched bonds) stays below, and the compression's rising pressure passes.
  const Loop plastic = run_loop(dir, "plastic", R"("yield_stress_MPa": 1.0, "hardening_MPa": 20)");
  EXPECT_EQ(plastic.plastic_loss.front(), 0.0);  // nothing yielded before the plates came
  EXPECT_GT(plastic.plastic_loss.back(), 0.0);
  EXPECT_GT(plastic.strain.back(), elastic.strain.back() + 0.005);
  // The yielding wall is softer: less plate work, and the flow dissipates a large share of it (the rest
  // goes to the fluid's viscosity and the bonds' damping, Eqs 4 and 16, and stays in the set cell).
  EXPECT_LT(plastic.plate_work.back(), elastic.plate_work.back());
  EXPECT_GT(plastic.plastic_loss.back(), 0.3 * plastic.plate_work.back());
  EXPECT_LT(std::abs(plastic.residual.back() - plastic.residual.front()),
            0.05 * std::abs(plastic.plate_work.back()) + 1e-15);
}

TEST(LoadUnload, AnUnloadStrainPastTheEndStrainIsRefused) {
  ScratchDir dir("load_unload_bad");
  const auto c = dir.write("case.json", R"({"compression": {"end_strain": 0.1, "unload_at_strain": 0.15}})");
  const auto r = run_cli({"run", c, "-o", dir.file("out.h5"), "--quiet"}, dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("compression.unload_at_strain = 0.15"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("compression.end_strain = 0.1"), std::string::npos) << r.err;
}
