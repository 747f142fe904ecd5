// A laterally periodic tissue (model.md §10b): cells that face their neighbours' images across the
// period, and forces, volumes and areas that do not depend on which image of a cell is stored.
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "core/periodic_box.hpp"
#include "engine/quasi_static.hpp"
#include "engine/settle.hpp"
#include "engine/simulation.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"
#include "small_cell.hpp"

using namespace cellsim;
using cellsim::testing::small_cell_case;

namespace {

// A periodic slab of the small cell (40 um), nx x ny cells to a period, nz layers.
Params slab_case(int nx, int ny, int nz, const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json doc = {
      {"tissue", {{"cells_x", nx}, {"cells_y", ny}, {"cells_z", nz}, {"wall_gap_um", 1.6}, {"lateral", "periodic"}}}};
  doc.merge_patch(extra);
  return small_cell_case(doc);
}

// The tissue with its period and the cells' positions in it stretched by `factor` (the cells whole).
Tissue stretched(Tissue t, double factor) {
  for (int c = 0; c < t.cells.count(); ++c) {
    const auto wall = t.wall_x.middleCols(t.cells.wall[c], t.cells.wall_count(c));
    Eigen::Vector3d by = (factor - 1) * wall.rowwise().mean();
    by.z() = 0;
    t.wall_x.middleCols(t.cells.wall[c], t.cells.wall_count(c)).colwise() += by;
    t.fluid_x.middleCols(t.cells.fluid[c], t.cells.fluid_count(c)).colwise() += by;
  }
  t.box.length_x_m *= factor;
  t.box.length_y_m *= factor;
  return t;
}

// The tissue with cell c's particles (fluid and wall) moved by `by`.
Tissue with_cell_moved(Tissue t, int c, const Eigen::Vector3d& by) {
  t.wall_x.middleCols(t.cells.wall[c], t.cells.wall_count(c)).colwise() += by;
  t.fluid_x.middleCols(t.cells.fluid[c], t.cells.fluid_count(c)).colwise() += by;
  return t;
}

double largest(const Eigen::Matrix3Xd& m) { return m.colwise().norm().maxCoeff(); }

}  // namespace

TEST(PeriodicBox, TakesTheNearestImageAlongThePeriodicAxesOnly) {
  const PeriodicBox box{100e-6, 80e-6};
  const Eigen::Vector3d d = box.nearest_image(Eigen::Vector3d(70e-6, -50e-6, 300e-6));
  EXPECT_NEAR(d.x(), -30e-6, 1e-18);
  EXPECT_NEAR(d.y(), 30e-6, 1e-18);
  EXPECT_EQ(d.z(), 300e-6);  // z is between the plates: never wrapped
  EXPECT_EQ(PeriodicBox{}.nearest_image(Eigen::Vector3d(1, 2, 3)), Eigen::Vector3d(1, 2, 3));
  EXPECT_DOUBLE_EQ(box.area_m2(), 8e-9);
}

TEST(PeriodicTissue, EveryCellIsBondedToItsNeighboursOnAllFourSidesAcrossThePeriod) {
  Params p = slab_case(2, 2, 1);
  const Tissue t = build_tissue(p);
  ASSERT_EQ(t.cells.count(), 4);
  const double d = p.centre_distance_over_diameter * p.diameter_m;
  EXPECT_DOUBLE_EQ(t.box.length_x_m, 2 * d);
  EXPECT_DOUBLE_EQ(t.box.length_y_m, 2 * d);
  // A cluster's corner cell has two lateral faces; in the period every cell has four, two of them with
  // the images of the same neighbours.
  const std::vector<int> cell = t.cells.cell_of_wall();
  std::vector<std::array<int, 4>> sides(4, {0, 0, 0, 0});  // bonds leaving toward +x, -x, +y, -y
  for (const LamellaBond& bond : t.lamella) {
    const Eigen::Vector3d ab = t.box.nearest_image(t.wall_x.col(bond.b) - t.wall_x.col(bond.a));
    EXPECT_NEAR(bond.length_m, ab.norm(), 1e-12);
    ASSERT_LT(bond.length_m, 1.5 * *p.wall_gap_m);
    const int side = std::abs(ab.x()) > std::abs(ab.y()) ? (ab.x() > 0 ? 0 : 1) : (ab.y() > 0 ? 2 : 3);
    ++sides[cell[bond.a]][side];
    ++sides[cell[bond.b]][side ^ 1];  // the partner sees the bond from the other side
  }
  for (int c = 0; c < 4; ++c)
    for (int side = 0; side < 4; ++side) EXPECT_GT(sides[c][side], 3) << "cell " << c << " side " << side;
  // Facing walls across the period are one gap apart, as inside it.
  double closest = INFINITY;
  for (Eigen::Index k = 0; k < t.wall_x.cols(); ++k)
    for (Eigen::Index l = k + 1; l < t.wall_x.cols(); ++l)
      if (cell[k] != cell[l]) closest = std::min(closest, t.box.nearest_image(t.wall_x.col(k) - t.wall_x.col(l)).norm());
  EXPECT_GE(closest, *p.wall_gap_m * (1 - 1e-9));
  EXPECT_LT(closest, 1.2 * *p.wall_gap_m);
}

// The must-show test of a periodic tissue: a cell stored across the boundary (moved by a period) has the
// same forces, volume and area as where it was, and so have its neighbours.
TEST(PeriodicTissue, ACellMovedByAPeriodFeelsAndExertsTheSameForces) {
  Params p = slab_case(2, 2, 2);
  const Tissue t = build_tissue(p);
  Simulation inside(p, t);
  const Eigen::Vector3d period_x(t.box.length_x_m, 0, 0), period_y(0, t.box.length_y_m, 0);
  Simulation across(p, with_cell_moved(with_cell_moved(t, 0, period_x), 5, -period_x - period_y));
  ASSERT_GT(inside.neighbours().wall_wall().pairs, 0u);
  EXPECT_EQ(across.neighbours().wall_wall().pairs, inside.neighbours().wall_wall().pairs);
  const double wall_scale = largest(inside.wall_force()), fluid_scale = largest(inside.fluid_force());
  EXPECT_LT(largest(across.wall_force() - inside.wall_force()), 1e-9 * wall_scale);
  EXPECT_LT(largest(across.fluid_force() - inside.fluid_force()), 1e-9 * fluid_scale);
  for (int c = 0; c < t.cells.count(); ++c) {
    EXPECT_NEAR(across.surface().cell_volume_m3[c], inside.surface().cell_volume_m3[c],
                1e-12 * inside.surface().cell_volume_m3[c]);
    EXPECT_NEAR(across.surface().cell_area_m2[c], inside.surface().cell_area_m2[c], 1e-12 * inside.surface().cell_area_m2[c]);
  }
  // Newton's third law across the period: the forces of the whole tissue add up to nothing.
  const Eigen::Vector3d total = across.wall_force().rowwise().sum() + across.fluid_force().rowwise().sum();
  EXPECT_LT(total.norm(), 1e-9 * wall_scale);
  EXPECT_NO_THROW(across.check_containment());
}

// A state saved from a slab whose period has shrunk (a dried slab, continued with --from) keeps that
// period in the list of wall pairs between cells too, not the period the case builds: restored into a
// simulation of the slab as built, the squeezed slab meets its walls across the period exactly as the
// simulation that squeezed it does. (Before, the list kept the built period: the dried X/X0 = 0.1 slab,
// 171 um against 255 um, had no contact across it and let a wall into its neighbour.)
TEST(PeriodicTissue, ARestoredStateKeepsItsPeriodForTheContactsAcrossIt) {
  Params p = slab_case(2, 2, 1);
  const Tissue built = build_tissue(p);
  const Simulation squeezed(p, stretched(built, 0.97));
  Simulation restored(p, built);
  restored.restore(squeezed.state());
  ASSERT_LT(squeezed.state().lateral_stress_x_Pa, -1e3);  // Pa: the walls touch across the period
  EXPECT_EQ(restored.neighbours().wall_wall().pairs, squeezed.neighbours().wall_wall().pairs);
  EXPECT_EQ(restored.state().lateral_stress_x_Pa, squeezed.state().lateral_stress_x_Pa);
  EXPECT_EQ(restored.state().lateral_stress_y_Pa, squeezed.state().lateral_stress_y_Pa);
  EXPECT_LT(largest(restored.wall_force() - squeezed.wall_force()), 1e-12 * largest(squeezed.wall_force()));
}

// Stepped, the two stored images move alike: after 200 steps (the cells as built are not at rest) each
// particle of the moved cell is where the other's is, a period away (to round-off), and no mass or
// particle was lost.
TEST(PeriodicTissue, ACellStoredAcrossThePeriodMovesAsTheCellInside) {
  Params p = slab_case(2, 2, 1);
  const Tissue t = build_tissue(p);
  const Eigen::Vector3d period_x(t.box.length_x_m, 0, 0);
  Simulation inside(p, t), across(p, with_cell_moved(t, 1, period_x));
  for (int i = 0; i < 200; ++i) {
    inside.step();
    across.step();
  }
  const State &a = inside.state(), &b = across.state();
  Eigen::Matrix3Xd moved_back = b.wall.x;
  // a period away: the period of now, which has followed the cells (model.md §10b)
  moved_back.middleCols(t.cells.wall[1], t.cells.wall_count(1)).colwise() -= Eigen::Vector3d(b.box.length_x_m, 0, 0);
  EXPECT_LT(largest(moved_back - a.wall.x), 1e-9 * p.diameter_m);
  EXPECT_LT(largest(b.wall.v - a.wall.v), 1e-6 * largest(a.wall.v) + 1e-12);
  EXPECT_NEAR(b.fluid.m.sum(), a.fluid.m.sum(), 1e-12 * a.fluid.m.sum());
  EXPECT_EQ(b.fluid.size(), a.fluid.size());
  // Momentum: the period carries none in or out, so both stores hold the same (the model's own damping
  // and mass transfer change it alike in both).
  const auto momentum = [](const State& s) {
    return Eigen::Vector3d(s.fluid.v * s.fluid.m + s.wall.v.rowwise().sum() * s.wall.mass_kg);
  };
  const double scale = (a.fluid.v.colwise().norm().transpose().array() * a.fluid.m.array()).sum();
  EXPECT_LT((momentum(b) - momentum(a)).norm(), 1e-9 * scale);
}

TEST(PeriodicTissue, WallsThatMeetThroughThePeriodStopTheRun) {
  Params p = slab_case(2, 2, 1);
  const Tissue t = build_tissue(p);
  // Cell 1 moved by a period less half a cell: its image now overlaps cell 0.
  Simulation sim(p, with_cell_moved(t, 1, Eigen::Vector3d(t.box.length_x_m - 0.5 * p.diameter_m, 0, 0)));
  try {
    sim.check_containment();
    FAIL() << "no failure";
  } catch (const NumericalFailure& e) {
    EXPECT_NE(std::string(e.what()).find("the walls interpenetrate"), std::string::npos) << e.what();
  }
}

TEST(PeriodicTissue, APeriodOfOneCellOrAnOddNumberOfHexagonalRowsIsRefusedNamingTheKeys) {
  for (const auto& [nx, ny, packing, key] : {std::tuple{1, 2, "cubic", "tissue.cells_x"},
                                             std::tuple{2, 1, "cubic", "tissue.cells_y"},
                                             std::tuple{2, 3, "close", "even tissue.cells_y"}}) {
    Params p = slab_case(nx, ny, 1, {{"tissue", {{"packing", packing}}}});
    try {
      build_tissue(p);
      FAIL() << nx << " x " << ny << " " << packing << ": no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("tissue.lateral"), std::string::npos) << e.what();
    }
  }
}

// An unconfined compression asks a period to follow: a cluster (free sides) has none.
TEST(PeriodicTissue, AnUnconfinedClusterIsRefusedNamingBothKeys) {
  Params p = slab_case(2, 2, 1, {{"tissue", {{"lateral", "free"}}}, {"compression", {{"lateral", "unconfined"}}}});
  try {
    build_tissue(p);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("compression.lateral = unconfined"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("tissue.lateral = periodic"), std::string::npos) << e.what();
  }
}

TEST(PeriodicTissue, PlatesCoverThePeriodAndTheStressIsOverItsArea) {
  Params p = slab_case(2, 2, 1);
  Simulation sim(p, build_tissue(p));
  sim.start_compression();
  State& s = sim.mutable_state();
  s.plates.top_z_m -= 0.1 * p.diameter_m;  // into the slab: every top wall particle near it is pushed
  s.plates.force_top_N = 1e-3;
  const Record r = sim.record();
  EXPECT_DOUBLE_EQ(r.plate_stress_Pa, 1e-3 / s.box.area_m2());
  EXPECT_DOUBLE_EQ(r.footprint_stress_Pa, 1e-3 / s.box.area_m2());  // the slab's footprint is its period
  const PlateLaw law = plate_law(p);
  EXPECT_TRUE(std::isinf(law.length_m) && std::isinf(law.width_m));
  // The slab's volume is the period's area times its height; its porosity lies between 0 and 1.
  EXPECT_GT(r.porosity, 0);
  EXPECT_LT(r.porosity, 0.5);
}

// A slab of four layers between the plates (model.md §10c): the plates flatten the layers they touch
// more than the interior, so the gauge between the centroid planes of layers 1 and 2 reads less than the
// nominal strain; no cell leaks, no wall passes through another, and no lamella bond breaks.
TEST(PeriodicTissue, AFourLayerSlabCompressesWithTheInteriorGaugeBelowTheNominalStrain) {
  // a wall gap of 3 um, about half the small cell's wall spacing (at 1.6 um, as test_tissue's, walls of
  // 162 particles slip through each other by strain 0.04, in a cluster as in the slab)
  Params p = slab_case(2, 2, 4, {{"compression", {{"plate_speed_m_s", 2}}}, {"tissue", {{"wall_gap_um", 3}}}});
  Simulation sim(p, build_tissue(p));
  ASSERT_EQ(sim.cells().layers(), 4);
  for (int i = 0; i < 1000; ++i) sim.step();
  sim.start_compression();
  const Record start = sim.record();
  EXPECT_NEAR(start.gauge_strain, 0, 1e-15);
  ASSERT_EQ(start.layer_centroid_z_m.size(), 4u);
  for (int k = 1; k < 4; ++k) EXPECT_GT(start.layer_centroid_z_m[k], start.layer_centroid_z_m[k - 1] + 0.5 * p.diameter_m);
  while (sim.nominal_strain() < 0.04) sim.step();
  const Record r = sim.record();
  EXPECT_GT(r.gauge_strain, 0.1 * r.nominal_strain);
  EXPECT_LT(r.gauge_strain, r.nominal_strain);
  // the two layers the plates touch are flattened more than either interior layer
  const auto& layer = r.layer_height_strain;
  EXPECT_GT(std::min(layer[0], layer[3]), std::max(layer[1], layer[2]));
  EXPECT_DOUBLE_EQ(r.plate_stress_Pa, r.plate_force_top_N / sim.state().box.area_m2());
  EXPECT_GT(r.plate_stress_Pa, 0);
  EXPECT_EQ(r.lamella_intact, static_cast<double>(sim.lamella().size()));
  EXPECT_NO_THROW(sim.check_containment());
  EXPECT_NEAR(r.fluid_mass_kg, start.fluid_mass_kg, 1e-5 * start.fluid_mass_kg);  // L_p 1e-12: water barely moves
}

// The lateral stress (model.md §10b): a slab whose period is stretched is in tension (its lamella bonds
// across the period pull), one squeezed is in compression (its walls touch across the period), alike
// along x and y in a cubic slab, and the slab as built is free of it.
TEST(PeriodicTissue, AStretchedPeriodIsInTensionAndASqueezedOneInCompression) {
  Params p = slab_case(2, 2, 1);
  const Tissue t = build_tissue(p);
  const auto stress = [&](double factor) {
    Simulation sim(p, stretched(t, factor));
    return Eigen::Vector2d(sim.state().lateral_stress_x_Pa, sim.state().lateral_stress_y_Pa);
  };
  const Eigen::Vector2d built = stress(1.0), pulled = stress(1.01), pushed = stress(0.99);
  EXPECT_GT(pulled.minCoeff(), 1e3);  // Pa
  EXPECT_LT(pushed.maxCoeff(), -1e3);
  EXPECT_LT(built.cwiseAbs().maxCoeff(), 1e-3 * pulled.minCoeff());
  EXPECT_NEAR(pulled.x(), pulled.y(), 0.2 * pulled.x());
  EXPECT_NEAR(pushed.x(), pushed.y(), 0.2 * std::abs(pushed.x()));
}

// Unconfined, a stretched period follows its tension back: the period shrinks and the tension falls;
// confined in compression, the period does not move.
TEST(PeriodicTissue, AnUnconfinedPeriodFollowsZeroLateralStressAndAConfinedOneHoldsInCompression) {
  Params p = slab_case(2, 2, 1, {{"tissue", {{"period_viscosity_Pa_s", 0.1}}}, {"compression", {{"lateral", "unconfined"}}}});
  const Tissue t = stretched(build_tissue(p), 1.01);
  Simulation sim(p, t);
  const double tension = sim.state().lateral_stress_x_Pa;
  for (int i = 0; i < 2000; ++i) sim.step();
  EXPECT_LT(sim.state().box.length_x_m, t.box.length_x_m * (1 - 0.003));
  EXPECT_LT(std::abs(sim.state().lateral_stress_x_Pa), 0.5 * tension);
  EXPECT_NO_THROW(sim.check_containment());

  Params held = slab_case(2, 2, 1);  // confined: follows in drying, holds in compression
  build_tissue(held);                // (its derived parameters)
  Simulation confined(held, t);
  for (int i = 0; i < 200; ++i) confined.step();
  const PeriodicBox before = confined.state().box;
  EXPECT_LT(before.length_x_m, t.box.length_x_m);
  confined.start_compression();
  for (int i = 0; i < 200; ++i) confined.step();
  EXPECT_EQ(confined.state().box.length_x_m, before.length_x_m);
  EXPECT_EQ(confined.state().box.length_y_m, before.length_y_m);
  EXPECT_TRUE(std::isfinite(confined.state().lateral_stress_x_Pa));  // still measured: the confining stress
}

// Drying (model.md §10b): the period follows the cells as they shrink, as far as their bonds across it
// pull, and ends free of lateral stress. The small cell's 2 x 2 slab after 30 us of drying to X/X0 = 0.5
// (the drying ramp takes 20 us).
TEST(PeriodicTissue, ThePeriodShrinksWithTheDryingCellsAndEndsFreeOfLateralStress) {
  Params p = slab_case(2, 2, 1, {{"drying", {{"dryness", 0.5}}}, {"tissue", {{"wall_gap_um", 3}}}});
  const Tissue t = build_tissue(p);
  Simulation sim(p, t);
  settle(sim, p.settle_max_iterations, p.settle_tolerance);
  const double period0 = sim.state().box.length_x_m, volume0 = sim.surface().volume_m3;
  for (int i = 0; i < 60000; ++i) sim.step();
  const double shrink = sim.state().box.length_x_m / period0;
  const double cells_shrink = std::cbrt(sim.surface().volume_m3 / volume0);
  EXPECT_LT(cells_shrink, 0.95);  // the cells have dried
  EXPECT_NEAR(shrink, cells_shrink, 0.05);
  EXPECT_NEAR(sim.state().box.length_y_m / period0, shrink, 0.01);  // alike along y
  EXPECT_LT(std::abs(sim.state().lateral_stress_x_Pa), 5e3);       // Pa: near zero, beside a turgor of 1e5
  EXPECT_EQ(std::count(sim.state().lamella_intact.begin(), sim.state().lamella_intact.end(), 1),
            static_cast<long>(t.lamella.size()));
  EXPECT_NO_THROW(sim.check_containment());
}

// The viscous follower takes sigma^2 L_x L_y H dt / eta_p a step, the account's period loss (model.md §8):
// with it the account of a slab of closed cells drying in the dynamic scheme closes to a hundredth of that
// loss (without it, the residual is minus the loss). The small cell's 2 x 2 slab, 30 us to X/X0 = 0.5.
TEST(PeriodicTissue, TheFollowersLossClosesTheDryingSlabsEnergyAccount) {
  Params p = slab_case(2, 2, 1, {{"fluid", {{"model", "cavity"}}}, {"drying", {{"dryness", 0.5}}},
                                 {"tissue", {{"wall_gap_um", 3}}}});
  const Tissue t = build_tissue(p);
  Simulation sim(p, t);
  settle(sim, p.settle_max_iterations, p.settle_tolerance);
  EXPECT_EQ(sim.record().energy_residual_J, 0.0);  // the account starts closed, the settle's damage in its reference
  for (int i = 0; i < 30000; ++i) sim.step();
  const Record dried = sim.record();
  EXPECT_GT(dried.energy[kPeriodLoss], 1e-3 * dried.energy[kDrive]);
  EXPECT_LT(std::abs(dried.energy_residual_J), 1e-2 * dried.energy[kPeriodLoss]);
}

// Quasi-static, with closed cells (engine/quasi_static.hpp): the period is part of every equilibrium. The
// small cell's 2 x 2 slab dried to X/X0 = 0.5 ends each step with its lateral stress within the
// tolerance of the load, its period shrunk with the cells, its bonds whole and the energy account closed;
// compressed unconfined, the period follows and stays free of lateral stress, confined it holds.
TEST(PeriodicTissue, QuasiStaticThePeriodIsAtEquilibriumAtEveryStep) {
  Params p = slab_case(2, 2, 1, {{"fluid", {{"model", "cavity"}}}, {"time", {{"scheme", "quasi_static"}, {"dt_ns", 500}}},
                                 {"drying", {{"dryness", 0.5}}}, {"tissue", {{"wall_gap_um", 3}}}});
  const Tissue t = build_tissue(p);
  Simulation sim(p, t);
  settle(sim, p.settle_max_iterations, p.settle_tolerance);
  QuasiStaticScheme drying(sim);
  const double period0 = sim.state().box.length_x_m, volume0 = sim.surface().volume_m3;
  // The lateral stress over the load scale, max(P_T0, the largest |P| of a cell).
  const auto stress_over_load = [](const Simulation& at) {
    double load_Pa = at.params().turgor_Pa;
    for (double P : at.cell_mean_fluid_pressure_Pa()) load_Pa = std::max(load_Pa, std::abs(P));
    return std::max(std::abs(at.state().lateral_stress_x_Pa), std::abs(at.state().lateral_stress_y_Pa)) / load_Pa;
  };
  double most = 0;
  for (int n = 0; n < 60; ++n) {  // the 20 us ramp and 10 us beyond
    drying.step();
    most = std::max(most, stress_over_load(sim));
  }
  EXPECT_LE(most, p.equilibrium_tolerance);
  const double shrink = sim.state().box.length_x_m / period0;
  const double cells_shrink = std::cbrt(sim.surface().volume_m3 / volume0);
  EXPECT_LT(cells_shrink, 0.95);  // the cells have dried
  EXPECT_NEAR(shrink, cells_shrink, 0.05);
  EXPECT_NEAR(sim.state().box.length_y_m / period0, shrink, 0.01);  // alike along y
  EXPECT_EQ(std::count(sim.state().lamella_intact.begin(), sim.state().lamella_intact.end(), 1),
            static_cast<long>(t.lamella.size()));
  const Record dried = sim.record();
  EXPECT_LT(std::abs(dried.energy_residual_J), 1e-3 * std::abs(dried.energy[kDrive]));

  for (const char* lateral : {"unconfined", "confined"}) {
    Params q = p;
    q.compression_lateral = std::string(lateral) == "unconfined" ? kLateralUnconfined : kLateralConfined;
    Simulation squeezed(q, t);
    squeezed.restore(sim.state());
    QuasiStaticScheme squeezing(squeezed);
    squeezing.start_compression();
    const PeriodicBox before = squeezed.state().box;
    double most_squeezed = 0;
    while (squeezed.nominal_strain() < 0.05) {
      squeezing.step();
      most_squeezed = std::max(most_squeezed, stress_over_load(squeezed));
    }
    if (q.compression_lateral == kLateralUnconfined) {
      EXPECT_LE(most_squeezed, q.equilibrium_tolerance);
      EXPECT_GT(squeezed.state().box.length_x_m, before.length_x_m);  // squeezed, the slab spreads
    } else {
      EXPECT_EQ(squeezed.state().box.length_x_m, before.length_x_m);
      EXPECT_GT(stress_over_load(squeezed), 10 * q.equilibrium_tolerance);  // the die pushes back
      EXPECT_LT(squeezed.state().lateral_stress_x_Pa, 0.0);
    }
    const Record r = squeezed.record();
    EXPECT_LT(std::abs(r.energy_residual_J), 1e-6 * r.energy[kPlateWork]) << lateral;
  }
  // The period's viscosity is the dynamic scheme's: a quasi-static case that gives it is told so.
  const nlohmann::json doc = {{"fluid", {{"model", "cavity"}}}, {"time", {{"scheme", "quasi_static"}}},
                              {"tissue", {{"cells_x", 2}, {"lateral", "periodic"}, {"period_viscosity_Pa_s", 20}}}};
  EXPECT_EQ(keys_the_case_ignores(doc, validate_case(doc)), std::vector<std::string>{"tissue.period_viscosity_Pa_s"});
}

// Close packing in a period (hexagonal layers stacked A, B, C, with a seeded spread of diameters): a
// cell of the middle layer meets twelve neighbours, six in its layer and three above and below, most of
// them images across the period, each a distinct (cell, image) pair.
TEST(PeriodicTissue, AClosePackedSlabGivesAMiddleCellTwelveNeighboursAcrossThePeriod) {
  Params p = slab_case(2, 2, 3, {{"tissue", {{"packing", "close"}, {"diameter_spread", 0.05}, {"seed", 7},
                                            {"centre_distance_over_diameter", 0.9}}}});
  const Tissue t = build_tissue(p);
  ASSERT_EQ(t.cells.count(), 12);
  const std::vector<int> cell = t.cells.cell_of_wall();
  // (partner cell, its image as whole periods) of every bond, from each side
  std::vector<std::set<std::tuple<int, long, long>>> partners(12);
  for (const LamellaBond& bond : t.lamella) {
    const Eigen::Vector3d direct = t.wall_x.col(bond.b) - t.wall_x.col(bond.a);
    const Eigen::Vector3d shift = t.box.nearest_image(direct) - direct;
    const long ix = std::lround(shift.x() / t.box.length_x_m), iy = std::lround(shift.y() / t.box.length_y_m);
    partners[cell[bond.a]].insert({cell[bond.b], ix, iy});
    partners[cell[bond.b]].insert({cell[bond.a], -ix, -iy});
  }
  for (int c = 4; c < 8; ++c) EXPECT_EQ(partners[c].size(), 12u) << "cell " << c;  // the middle layer
  for (int c : {0, 11}) EXPECT_EQ(partners[c].size(), 9u) << "cell " << c;        // six in the layer, three beside
  EXPECT_NEAR(t.box.length_y_m, std::sqrt(3.0) * 0.9 * p.diameter_m, 1e-12);     // two rows of sqrt 3 / 2 d
}

// A period viscosity so low that the period would jump stops the run, naming the key.
TEST(PeriodicTissue, APeriodThatWouldJumpStopsTheRunNamingTheKey) {
  Params p = slab_case(2, 2, 1, {{"tissue", {{"period_viscosity_Pa_s", 1e-9}}}, {"compression", {{"lateral", "unconfined"}}}});
  Simulation sim(p, stretched(build_tissue(p), 1.01));
  try {
    sim.step();
    FAIL() << "no failure";
  } catch (const NumericalFailure& e) {
    EXPECT_NE(std::string(e.what()).find("tissue.period_viscosity_Pa_s"), std::string::npos) << e.what();
  }
}

// The period's explicit step (model.md §10b) moves the cells whole, so the stress answers it with the
// stiffness K of the bonds between them: the step rings with factor 1 - K dt / eta_p. For the small
// test cell's 2 x 2 slab K dt is ~0.04 Pa s: at eta_p = 0.02 the lateral stress changes sign every step
// and grows until the period would jump (the run stops, naming the key); at 0.05 it does not ring.
TEST(PeriodicTissue, ThePeriodsStepRingsAndGrowsBelowHalfTheBondStiffnessTimesDt) {
  const auto lateral_stress = [](double eta_Pa_s, bool& stopped) {
    Params p = slab_case(2, 2, 1, {{"tissue", {{"period_viscosity_Pa_s", eta_Pa_s}}},
                                   {"compression", {{"lateral", "unconfined"}}}});
    Simulation sim(p, stretched(build_tissue(p), 1.0001));
    std::vector<double> stress;
    stopped = false;
    try {
      for (int i = 0; i < 30; ++i) {
        sim.step();
        stress.push_back(sim.state().lateral_stress_x_Pa);
      }
    } catch (const NumericalFailure& e) {
      EXPECT_NE(std::string(e.what()).find("tissue.period_viscosity_Pa_s"), std::string::npos) << e.what();
      stopped = true;
    }
    return stress;
  };
  const auto sign_changes = [](const std::vector<double>& x) {
    int n = 0;
    for (std::size_t i = 1; i < x.size(); ++i) n += (x[i] > 0) != (x[i - 1] > 0);
    return n;
  };
  bool stopped = false;
  const std::vector<double> ringing = lateral_stress(0.02, stopped);
  EXPECT_TRUE(stopped);
  ASSERT_GE(ringing.size(), 3u);
  EXPECT_EQ(sign_changes(ringing), static_cast<int>(ringing.size()) - 1);  // every step
  EXPECT_GT(std::abs(ringing.back()), std::abs(ringing.front()));          // growing
  const std::vector<double> damped = lateral_stress(0.05, stopped);
  EXPECT_FALSE(stopped);
  EXPECT_LE(sign_changes(damped), 1);
}
