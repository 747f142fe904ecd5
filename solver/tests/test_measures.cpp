// What a record measures (measures.cpp, model.md §8) against values computed here from the
// particles: Eq 6's smoothing length, contact area (Eq 22's rule, footprint included), the plate
// force, the three stresses and the nominal strain.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "engine/simulation.hpp"
#include "physics/lennard_jones.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"
#include "small_cell.hpp"

using namespace cellsim;

namespace {

Params small_case() { return cellsim::testing::small_cell_case(); }

}  // namespace

TEST(Measures, SmoothingLengthFollowsTheEquivalentDiameterEq6) {
  Params p = small_case();
  Simulation sim(p, build_tissue(p));
  EXPECT_DOUBLE_EQ(sim.state().smoothing_length_m, *p.h0_m);  // h = h0 at the start
  // Scale the whole cell by 1.1: D grows by 1.1, so must h.
  sim.mutable_state().wall.x *= 1.1;
  sim.mutable_state().fluid.x *= 1.1;
  sim.refresh_rates();
  EXPECT_NEAR(sim.state().smoothing_length_m / *p.h0_m, 1.1, 1e-12);
  const Record r = sim.record();
  EXPECT_NEAR(r.smoothing_length_m / *p.h0_m, r.equivalent_diameter_m / sim.state().reference_diameter_m, 1e-12);
  EXPECT_NEAR(M_PI / 6 * std::pow(r.equivalent_diameter_m, 3), r.volume_m3, 1e-12 * r.volume_m3);
}

TEST(Measures, ContactAreaForceStressesAndStrainUnderThePlates) {
  Params p = small_case();
  p.plate_length_m = 16e-6;  // a footprint narrower than the 40 um cell: particles beside it do not count
  p.plate_width_m = 16e-6;
  Simulation sim(p, build_tissue(p));
  sim.start_compression();
  State& s = sim.mutable_state();
  s.plates.top_z_m -= p.plate_gap_m + 4e-6;  // the top plate 4 um into the cell's range
  s.plates.bottom_z_m += 2e-6;
  sim.refresh_rates();
  const Record r = sim.record();

  // Independent count: triangle areas by cross products, a third to each corner; contact is within
  // r_pw of a plate and inside its footprint; force k_pw (r_pw - d) on the top plate.
  const auto& x = s.wall.x;
  const WallMesh& mesh = sim.mesh();
  Eigen::VectorXd owned = Eigen::VectorXd::Zero(x.cols());
  for (const auto& t : mesh.triangles) {
    const double a = 0.5 * (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0])).norm();
    for (int v : t) owned[v] += a / 3;
  }
  double area = 0, area_top = 0, force_top = 0;
  int count = 0, beside_footprint = 0;
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    const double d_top = s.plates.top_z_m - x(2, k), d_bottom = x(2, k) - s.plates.bottom_z_m;
    const bool in_range = d_top < p.plate_range_m || d_bottom < p.plate_range_m;
    const bool in_footprint = std::abs(x(0, k) - s.plates.axis_x_m) <= 0.5 * p.plate_length_m &&
                              std::abs(x(1, k) - s.plates.axis_y_m) <= 0.5 * p.plate_width_m;
    if (in_range && !in_footprint) ++beside_footprint;
    if (!in_range || !in_footprint) continue;
    area += owned[k];
    ++count;
    if (d_top < p.plate_range_m) force_top += p.plate_stiffness_N_m * (p.plate_range_m - d_top);
    if (d_top < p.plate_range_m) area_top += owned[k];
  }
  ASSERT_GT(count, 2);
  ASSERT_GT(beside_footprint, 0) << "the test needs particles in range but beside the footprint";
  EXPECT_EQ(r.contact_count, count);
  EXPECT_NEAR(r.contact_area_m2, area, 1e-12 * area);
  EXPECT_NEAR(r.plate_force_top_N, force_top, 1e-12 * force_top);
  EXPECT_NEAR(r.plate_stress_Pa, force_top / (p.plate_length_m * p.plate_width_m), 1e-9 * r.plate_stress_Pa);
  ASSERT_GT(area_top, 0);
  ASSERT_LT(area_top, area) << "the test needs both plates in contact";
  EXPECT_NEAR(r.contact_area_top_m2, area_top, 1e-12 * area_top);
  EXPECT_NEAR(r.contact_stress_Pa, force_top / area_top, 1e-9 * r.contact_stress_Pa);
  EXPECT_NEAR(r.pressure_load_N, r.mean_pressure_Pa * area_top, 1e-12 * std::abs(r.pressure_load_N));
  const Eigen::Vector3d centroid = x.rowwise().mean();
  const double Rc = (x.topRows<2>().colwise() - centroid.head<2>()).colwise().norm().maxCoeff();
  EXPECT_NEAR(r.section_stress_Pa, force_top / (M_PI * Rc * Rc), 1e-9 * r.section_stress_Pa);
  const double H = x.row(2).maxCoeff() - x.row(2).minCoeff();
  EXPECT_NEAR(r.nominal_strain, (s.plates.contact_height_m - H) / s.plates.contact_height_m, 1e-15);
}

// The load partition (load_partition.hpp): the fluid's part is the coupling force on the particles
// under the top plate, summed here from the LJ law over every fluid particle; with the wall's part
// and the plate's reaction it adds up to the total force on those particles.
TEST(Measures, TopPlateLoadSplitsIntoFluidAndWallParts) {
  Params p = small_case();
  Simulation sim(p, build_tissue(p));
  sim.start_compression();
  State& s = sim.mutable_state();
  s.plates.top_z_m -= p.plate_gap_m + 4e-6;
  sim.refresh_rates();
  const Record r = sim.record();
  const auto& x = s.wall.x;
  const LennardJones lj{*p.r0_m, std::max(*p.r0_m, p.attraction_cutoff_over_h * s.smoothing_length_m),
                        p.repulsion_f0_N_m, p.attraction_f0_N_m};
  double fluid_up = 0, total_up = 0;
  int touching = 0;
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    if (s.plates.top_z_m - x(2, k) >= p.plate_range_m) continue;
    ++touching;
    total_up += sim.wall_force()(2, k);
    for (Eigen::Index i = 0; i < s.fluid.size(); ++i) {
      const Eigen::Vector3d xik = s.fluid.x.col(i) - x.col(k);
      fluid_up -= lj.f_of_r2(xik.squaredNorm()) * xik.z();  // the reaction on wall particle k
    }
  }
  ASSERT_GT(touching, 2);
  ASSERT_GT(r.plate_force_top_N, 0);
  EXPECT_GT(r.load_fluid_N, 0) << "the pressurised fluid pushes the wall up into the plate";
  EXPECT_NEAR(r.load_fluid_N, fluid_up, 1e-9 * std::abs(fluid_up));
  EXPECT_NEAR(r.load_fluid_N + r.load_wall_N - r.plate_force_top_N, total_up, 1e-9 * r.plate_force_top_N);
}

TEST(Measures, BeforeCompressionPlateQuantitiesAreNaN) {
  Params p = small_case();
  Simulation sim(p, build_tissue(p));
  const Record r = sim.record();
  EXPECT_TRUE(std::isnan(r.plate_force_top_N));
  EXPECT_TRUE(std::isnan(r.contact_area_m2));
  EXPECT_TRUE(std::isnan(r.plate_stress_Pa));
  EXPECT_TRUE(std::isnan(r.load_fluid_N));
  EXPECT_TRUE(std::isnan(r.pressure_load_N));
  EXPECT_NEAR(r.fluid_mass_ratio, 1.0, 1e-15);
}
