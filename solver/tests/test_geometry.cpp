// Geometry of the initial cell (model.md §1; issue: counts, area, volume, orientation, masses).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "engine/measures.hpp"
#include "geometry/cell.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"

using namespace cellsim;

namespace {

Params defaults_with(double diameter_um, int n_wall, int n_fluid) {
  nlohmann::json doc = {{"cell", {{"diameter_um", diameter_um}, {"n_wall", n_wall}, {"n_fluid", n_fluid}}}};
  return validate_case(doc);
}

void check_cell(double diameter_um, int n_wall, int n_fluid) {
  SCOPED_TRACE("D = " + std::to_string(diameter_um) + " um");
  Params p = defaults_with(diameter_um, n_wall, n_fluid);
  const Cell cell = build_cell(p);
  const double R = 0.5 * diameter_um * 1e-6;

  EXPECT_EQ(cell.wall_x.cols(), n_wall);
  EXPECT_EQ(cell.mesh.triangles.size(), static_cast<std::size_t>(2 * n_wall - 4));
  EXPECT_EQ(cell.mesh.bonds.size(), static_cast<std::size_t>(3 * n_wall - 6));
  EXPECT_EQ(cell.mesh.hinges.size(), cell.mesh.bonds.size());
  EXPECT_EQ(cell.fluid_x.cols(), n_fluid);

  // Triangulated sphere within 1 % of the exact area and volume.
  EXPECT_NEAR(wall_surface(cell.wall_x, cell.mesh).area_m2 / (4 * M_PI * R * R), 1.0, 0.01);
  EXPECT_NEAR(wall_surface(cell.wall_x, cell.mesh).volume_m3 / (4.0 / 3.0 * M_PI * R * R * R), 1.0, 0.01);

  // Every triangle outward: its normal points away from the centre.
  for (const auto& t : cell.mesh.triangles) {
    const Eigen::Vector3d a = cell.wall_x.col(t[0]), b = cell.wall_x.col(t[1]), c = cell.wall_x.col(t[2]);
    ASSERT_GT((b - a).cross(c - a).dot((a + b + c) / 3.0), 0.0);
  }
  // Every wall particle used, every bond distinct.
  std::set<std::pair<int, int>> unique_bonds;
  for (const auto& b : cell.mesh.bonds) unique_bonds.insert({b[0], b[1]});
  EXPECT_EQ(unique_bonds.size(), cell.mesh.bonds.size());

  // Fluid inside R - fill_gap, fill gap defaulting to 0.7 r0.
  ASSERT_TRUE(p.fill_gap_m && p.r0_m);
  EXPECT_DOUBLE_EQ(*p.fill_gap_m, 0.7 * *p.r0_m);
  EXPECT_LE(cell.fluid_x.colwise().norm().maxCoeff(), R - *p.fill_gap_m);

  // Total masses as in Table 3: fluid rho0 (4/3) pi R^3, wall 10 % of it.
  const double fluid_total = 1000.0 * 4.0 / 3.0 * M_PI * R * R * R;
  EXPECT_NEAR(cell.fluid_mass_kg * n_fluid / fluid_total, 1.0, 1e-12);
  EXPECT_NEAR(cell.wall_mass_kg * n_wall / (0.1 * fluid_total), 1.0, 1e-12);
}

}  // namespace

TEST(Geometry, DefaultCellMatchesPaperCountsAreaVolumeAndMasses) { check_cell(150, 2067, 3082); }

TEST(Geometry, LargeCellMatchesPaperCountsAreaVolumeAndMasses) { check_cell(200, 2516, 3708); }

TEST(Geometry, TableThreeMassesAtDefaultCell) {
  Params p = defaults_with(150, 2067, 3082);
  const Cell cell = build_cell(p);
  EXPECT_NEAR(cell.fluid_mass_kg * 3082, 1.767e-9, 0.001e-9);  // Table 3: initial fluid mass
  EXPECT_NEAR(cell.wall_mass_kg * 2067, 1.767e-10, 0.001e-10);  // Table 3: initial wall mass
}

TEST(Geometry, DerivedDefaultsFollowTheMesh) {
  const Params p = defaults_with(150, 2067, 3082);  // validated: its derived values resolved
  // model.md §4: r0 ~ 8 um for the default mesh; h0 = 6.8 um exactly for the default cell.
  EXPECT_NEAR(*p.r0_m, 8e-6, 0.5e-6);
  EXPECT_DOUBLE_EQ(*p.h0_m, 6.8e-6);
  Params big = defaults_with(200, 2516, 3708);
  const Cell big_cell = build_cell(big);
  Params ref = defaults_with(150, 2067, 3082);
  const Cell ref_cell = build_cell(ref);
  EXPECT_NEAR(*big.h0_m / 6.8e-6, big_cell.fluid_spacing_m / ref_cell.fluid_spacing_m, 1e-12);
}

TEST(Geometry, SmoothingRatioSetsH0FromTheSpacing) {
  Params paper = defaults_with(150, 2067, 3082);
  const Cell cell = build_cell(paper);
  EXPECT_NEAR(*paper.h_over_dx, 0.888, 0.001);  // the paper's 6.8 um at its spacing (~23 neighbours)
  EXPECT_NEAR(*paper.h0_m, *paper.h_over_dx * cell.fluid_spacing_m, 1e-18);
  for (const double ratio : {1.2, 1.5}) {  // a finer cell keeps the ratio, not the paper's h0 rule
    Params p = validate_case({{"fluid", {{"h_over_dx", ratio}}}, {"cell", {{"n_fluid", 8717}, {"n_wall", 4134}}}});
    const Cell fine = build_cell(p);
    EXPECT_DOUBLE_EQ(*p.h0_m, ratio * fine.fluid_spacing_m);
    EXPECT_DOUBLE_EQ(*p.h_over_dx, ratio);
  }
}

TEST(Geometry, H0AndSmoothingRatioTogetherAreRefused) {
  try {
    validate_case({{"fluid", {{"h_over_dx", 1.2}, {"h0_um", 8.0}}}});  // where the derived values are resolved
    FAIL() << "both keys accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fluid.h0_um"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("fluid.h_over_dx"), std::string::npos) << e.what();
  }
}

TEST(Geometry, ExplicitR0AndFillGapAreKept) {
  nlohmann::json doc = {{"coupling", {{"r0_um", 5.0}}}, {"cell", {{"fill_gap_um", 1.0}}}};
  Params p = validate_case(doc);
  const Cell cell = build_cell(p);
  EXPECT_DOUBLE_EQ(*p.r0_m, 5e-6);
  EXPECT_LE(cell.fluid_x.colwise().norm().maxCoeff(), 74e-6);
  EXPECT_GT(cell.fluid_x.colwise().norm().maxCoeff(), 73e-6);  // the lattice fills out to the limit
}

TEST(Geometry, LatticePointsAreTheNearestToTheCentre) {
  double farthest = 0;
  const Eigen::Matrix3Xd x = nearest_lattice_points(7, &farthest);
  EXPECT_DOUBLE_EQ(farthest, 1.0);  // origin + 6 face neighbours
  EXPECT_DOUBLE_EQ(x.colwise().norm().sum(), 6.0);
}

TEST(Geometry, ABuilderNeedsTheDerivedValuesResolvedFirst) {
  Params p = defaults_with(150, 642, 700);
  p.r0_m.reset();  // as a case before validate_case resolves it (h0 given, its ratio derived)
  p.h_over_dx.reset();
  EXPECT_THROW(build_tissue(p), std::logic_error);
  resolve_derived_geometry(p);
  EXPECT_EQ(build_tissue(p).wall_x, build_cell(p).wall_x);
}
