// A tissue of cells (model.md §10): its geometry, the walls between cells, and the separation of the
// cells' fluids.
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "core/errors.hpp"
#include "engine/simulation.hpp"
#include "geometry/cell.hpp"
#include "geometry/containment.hpp"
#include "geometry/tissue.hpp"
#include "physics/cell_contact.hpp"
#include "physics/lamella_law.hpp"
#include "small_cell.hpp"

using namespace cellsim;
using cellsim::testing::small_cell_case;

namespace {

// Tissues of the small cell (40 um), with the wall gap scaled as the cell is from the paper's (6 um at 150 um).
Params tissue_case(int nx, int ny, int nz, const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json doc = {{"tissue", {{"cells_x", nx}, {"cells_y", ny}, {"cells_z", nz}, {"wall_gap_um", 1.6}}}};
  doc.merge_patch(extra);
  return small_cell_case(doc);
}

// The smallest distance between wall particles of different cells.
double closest_walls(const Tissue& t) {
  double closest = INFINITY;
  const std::vector<int> cell = t.cells.cell_of_wall();
  for (Eigen::Index k = 0; k < t.wall_x.cols(); ++k)
    for (Eigen::Index l = k + 1; l < t.wall_x.cols(); ++l)
      if (cell[k] != cell[l]) closest = std::min(closest, (t.wall_x.col(k) - t.wall_x.col(l)).norm());
  return closest;
}

}  // namespace

TEST(Tissue, OneCellIsThePapersCell) {
  Params p = small_cell_case();
  Params q = p;
  const Cell cell = build_cell(p);
  const Tissue tissue = build_tissue(q);
  ASSERT_EQ(tissue.cells.count(), 1);
  EXPECT_EQ(tissue.wall_x, cell.wall_x);
  EXPECT_EQ(tissue.fluid_x, cell.fluid_x);
  EXPECT_EQ(tissue.mesh.triangles, cell.mesh.triangles);
  EXPECT_EQ(tissue.mesh.rest_length_m, cell.mesh.rest_length_m);
  EXPECT_TRUE((tissue.fluid_mass_kg.array() == cell.fluid_mass_kg).all());
  EXPECT_EQ(tissue.wall_mass_kg, cell.wall_mass_kg);
  EXPECT_TRUE(tissue.lamella.empty());
}

TEST(Tissue, CubicCellsHaveFlatFacesOneWallGapApartAndKeepTheirFluidInside) {
  Params p = tissue_case(2, 2, 2);
  const Tissue t = build_tissue(p);
  ASSERT_EQ(t.cells.count(), 8);
  const double gap = *p.wall_gap_m;
  // Facing walls are one gap apart (their particles do not line up: no closer, and not much farther).
  const double closest = closest_walls(t);
  EXPECT_GE(closest, gap * (1 - 1e-9));
  EXPECT_LT(closest, 1.2 * gap);
  const double sphere_volume = M_PI / 6 * std::pow(p.diameter_m, 3);
  for (int c = 0; c < 8; ++c) {
    const ClosedSurface wall(t.wall_x, t.mesh, c);
    EXPECT_EQ(first_particle_outside(t.fluid_x, t.cells.fluid[c], t.cells.fluid[c + 1], wall), -1) << c;
    for (int other = 0; other < 8; ++other) {
      if (other == c) continue;
      for (Eigen::Index i = t.cells.fluid[other]; i < t.cells.fluid[other + 1]; ++i)
        ASSERT_FALSE(wall.contains(t.fluid_x.col(i))) << "fluid " << i << " of cell " << other << " in cell " << c;
      for (Eigen::Index k = t.cells.wall[other]; k < t.cells.wall[other + 1]; ++k)
        ASSERT_FALSE(wall.contains(t.wall_x.col(k))) << "wall " << k << " of cell " << other << " in cell " << c;
    }
    // Three faces cut each corner cell: less than a sphere, far more than the cube between the faces.
    const double volume = wall_surface(t.wall_x, t.mesh).cell_volume_m3[c];
    EXPECT_LT(volume, 0.97 * sphere_volume);
    EXPECT_GT(volume, 0.8 * sphere_volume);
  }
  // Lamella bonds: between face neighbours only (12 faces in a 2 x 2 x 2 cube), each within 1.5 gaps.
  const std::vector<int> cell = t.cells.cell_of_wall();
  std::set<std::pair<int, int>> faces;
  for (const auto& b : t.lamella) {
    ASSERT_LT(b.a, b.b);
    ASSERT_NE(cell[b.a], cell[b.b]);
    EXPECT_GE(b.length_m, gap * (1 - 1e-9));
    EXPECT_LE(b.length_m, 1.5 * gap);
    faces.insert({cell[b.a], cell[b.b]});
  }
  EXPECT_EQ(faces.size(), 12u);
}

TEST(Tissue, ClosePackingGivesEachCellMoreFacesThanCubic) {
  const auto neighbours_of_cell = [](Params p) {
    const Tissue t = build_tissue(p);
    const std::vector<int> cell = t.cells.cell_of_wall();
    std::vector<std::set<int>> n(static_cast<std::size_t>(t.cells.count()));
    for (const auto& b : t.lamella) n[cell[b.a]].insert(cell[b.b]), n[cell[b.b]].insert(cell[b.a]);
    std::size_t most = 0;
    for (const auto& s : n) most = std::max(most, s.size());
    return most;
  };
  EXPECT_EQ(neighbours_of_cell(tissue_case(3, 3, 3)), 6u);  // the centre cell of a cube
  EXPECT_GE(neighbours_of_cell(tissue_case(3, 3, 3, {{"tissue", {{"packing", "close"}}}})), 9u);
}

TEST(Tissue, SpreadDiametersAreSeededAndReproducible) {
  const nlohmann::json spread = {{"tissue", {{"diameter_spread", 0.1}, {"seed", 7}}}};
  Params a = tissue_case(2, 2, 1, spread), b = tissue_case(2, 2, 1, spread),
         c = tissue_case(2, 2, 1, {{"tissue", {{"diameter_spread", 0.1}, {"seed", 8}}}});
  const Tissue ta = build_tissue(a), tb = build_tissue(b), tc = build_tissue(c);
  EXPECT_EQ(ta.wall_x, tb.wall_x);
  EXPECT_EQ(ta.fluid_x, tb.fluid_x);
  EXPECT_NE(ta.cells.wall, tc.cells.wall);  // other diameters, other particle counts
  EXPECT_GE(closest_walls(ta), *a.wall_gap_m * (1 - 1e-9));
}

TEST(Tissue, CellsThatOverlapTooMuchAreRefusedNamingTheKey) {
  // Centres 24 um apart, 14 um gaps: each face 24/2 - 14/2 = 5 um from the centre of a 20 um cell.
  Params p = tissue_case(2, 1, 1, {{"tissue", {{"centre_distance_over_diameter", 0.6}, {"wall_gap_um", 14}}}});
  try {
    build_tissue(p);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tissue.centre_distance_over_diameter"), std::string::npos) << e.what();
  }
}

TEST(Tissue, NeighbourListsKeepEachFluidInItsOwnCell) {
  Params p = tissue_case(2, 1, 1);
  Simulation sim(p, build_tissue(p));
  const CellRanges& cells = sim.cells();
  const std::vector<int> fluid_cell = cells.cell_of_fluid(), wall_cell = cells.cell_of_wall();
  const NeighbourLists& lists = sim.neighbours();
  const auto& ff = lists.fluid_fluid();
  std::size_t within = 0;
  for (int i = 0; i < ff.rows(); ++i)
    for (int q = ff.offset[i]; q < ff.offset[i + 1]; ++q) {
      const int j = ff.index[q];
      if (j == static_cast<int>(fluid_cell.size())) continue;  // padding
      ASSERT_EQ(fluid_cell[i], fluid_cell[j]);
      ++within;
    }
  EXPECT_GT(within, 0u);
  const auto& fw = lists.fluid_wall();
  for (int i = 0; i < fw.rows(); ++i)
    for (int q = fw.offset[i]; q < fw.offset[i + 1]; ++q) ASSERT_EQ(fluid_cell[i], wall_cell[fw.index[q]]);
  const auto& ww = lists.wall_wall();
  ASSERT_GT(ww.pairs, 0u);  // the two cells face each other
  for (int k = 0; k < ww.rows(); ++k)
    for (int q = ww.offset[k]; q < ww.offset[k + 1]; ++q) ASSERT_NE(wall_cell[k], wall_cell[ww.index[q]]);
}

// Two cells touch: whatever the fluid of one does, the forces on the other's fluid do not change.
TEST(Tissue, AFluidParticleNeverFeelsAnotherCellsFluid) {
  Params p = tissue_case(2, 1, 1);
  Simulation sim(p, build_tissue(p));
  const CellRanges& cells = sim.cells();
  const Eigen::Index n0 = cells.fluid_count(0);
  const Eigen::Matrix3Xd before = sim.fluid_force().leftCols(n0);
  const Eigen::Matrix3Xd before_1 = sim.fluid_force().rightCols(cells.fluid_count(1));
  State& s = sim.mutable_state();
  // Cell 1 (at +x) has its fluid crowd 2 um toward cell 0, move fast and grow denser.
  for (Eigen::Index i = cells.fluid[1]; i < cells.fluid[2]; ++i) {
    s.fluid.x(0, i) -= 2e-6;
    s.fluid.v.col(i) << -2.0, 1.0, 0.5;
    s.fluid.rho[i] *= 1.01;
  }
  sim.refresh_rates();
  EXPECT_EQ(sim.fluid_force().leftCols(n0), before);
  EXPECT_GT((sim.fluid_force().rightCols(cells.fluid_count(1)) - before_1).norm(), 0.0);  // cell 1 did change
}

// Two pairs of wall particles of different cells, across a 100 um period: 0 and 1 in contact 5.10 um
// apart (inside the 6 um gap); 2 and 3, 5.10 um apart across the period, bonded by a middle lamella
// opened 0.4 um and damaged to 0.5 um before (delta_0 = 51 nm): its secant branch.
class TwoPairs : public ::testing::Test {
 protected:
  TwoPairs() : x(3, 4) {
    x << 0, 5e-6, 0, 99e-6,  //
        0, 1e-6, 20e-6, 20e-6,  //
        0, 0, 0, 5e-6;
    wall_wall.offset = {0, 1, 1, 1, 1};
    wall_wall.index = {1};
  }
  const CellContactLaw law{6e-6, 1e3, LamellaLaw{1e3, 51e-6, 1.0e-6}};
  Eigen::Matrix3Xd x;
  const PeriodicBox box{100e-6, 100e-6};
  PairList wall_wall;
  const std::vector<LamellaBond> bonds = {{2, 3, std::hypot(1e-6, 5e-6) - 0.4e-6}};
  const std::vector<double> peak = {0.5e-6};
};

TEST(CellContact, RepulsionAndLamellaObeyNewtonsThirdLawAndTheirLaws) {
  // Brittle lamella (delta_f = 0): k = 2e3 N/m, breaking at 5 mN.
  CellContactLaw law{6e-6, 1e3, LamellaLaw{2e3, 5e-3, 0.0}};
  Eigen::Matrix3Xd x(3, 4);
  x << 0, 5e-6, 0, 0,  //
      0, 0, 20e-6, 27e-6,  //
      0, 0, 0, 1e-6;
  // Particles 0 (cell 0) and 1 (cell 1) are 5 um apart (inside the 6 um gap): no bond, contact only.
  PairList wall_wall;
  wall_wall.offset = {0, 1, 1, 1, 1};
  wall_wall.index = {1};
  // Particles 2 and 3: bonded at 6.5 um, now 7.07 um apart: a lamella in tension.
  const std::vector<LamellaBond> bonds = {{2, 3, 6.5e-6}};
  std::vector<char> intact = {1};
  std::vector<double> peak = {0.0};
  Eigen::Matrix3Xd force = Eigen::Matrix3Xd::Zero(3, 4);
  EXPECT_EQ(add_cell_contact_forces(x, wall_wall, bonds, law, PeriodicBox{}, intact, peak, force), 0);
  EXPECT_NEAR(force(0, 0), -1e3 * 1e-6, 1e-15);  // k_c (g - r), pushing 0 away from 1 (along -x)
  EXPECT_NEAR(force.col(0).norm(), 1e-3, 1e-15);
  const double r = (x.col(3) - x.col(2)).norm();
  const Eigen::Vector3d pull = 2e3 * (r - 6.5e-6) / r * (x.col(3) - x.col(2));  // on 2, toward 3
  EXPECT_NEAR((force.col(2) - pull).norm(), 0.0, 1e-15);
  EXPECT_NEAR(force.rowwise().sum().norm(), 0.0, 1e-18);  // Newton's third law
  EXPECT_EQ(force.col(1), -force.col(0));
  EXPECT_EQ(force.col(3), -force.col(2));
  EXPECT_NEAR(peak[0], r - 6.5e-6, 1e-18);

  // The brittle bond breaks, for good, when its tension passes the peak force (here 2.1 mN): at
  // 1.04 um of stretch (2.08 mN) it holds, at 1.06 um (2.12 mN) it breaks.
  law.lamella.peak_force_N = 2.1e-3;
  const PairList no_contact{{0, 0, 0, 0, 0}, {}, 0, 0};
  x.col(3) = x.col(2) + Eigen::Vector3d(0, 7.54e-6, 0);  // tension 2e3 x 1.04 um = 2.08 mN
  force.setZero();
  EXPECT_EQ(add_cell_contact_forces(x, no_contact, bonds, law, PeriodicBox{}, intact, peak, force), 0);
  EXPECT_EQ(intact[0], 1);
  EXPECT_NEAR(force(1, 2), 2.08e-3, 1e-12);
  x.col(3) = x.col(2) + Eigen::Vector3d(0, 7.56e-6, 0);  // 2.12 mN
  force.setZero();
  EXPECT_EQ(add_cell_contact_forces(x, no_contact, bonds, law, PeriodicBox{}, intact, peak, force), 1);
  EXPECT_EQ(intact[0], 0);
  EXPECT_EQ(force.norm(), 0.0);
  x.col(3) = x.col(2) + Eigen::Vector3d(0, 7.0e-6, 0);  // back within strength: stays broken
  EXPECT_EQ(add_cell_contact_forces(x, no_contact, bonds, law, PeriodicBox{}, intact, peak, force), 0);
  EXPECT_EQ(force.norm(), 0.0);
}

TEST(LamellaLaw, SoftensFromItsPeakToZeroAndDissipatesTheFractureEnergy) {
  // k = 1e3 N/m, F_max = 51 uN (delta_0 = 51 nm); G_f = 1 J/m^2 over a_w = 34 um^2: delta_f = 1.333 um.
  const double a_w = 34e-12, f_max = 51e-6;
  const LamellaLaw law{1e3, f_max, lamella_break_opening_m(1.0, a_w, f_max)};
  EXPECT_NEAR(law.break_opening_m, 2.0 * 34e-12 / 51e-6, 1e-18);
  EXPECT_NEAR(law.elastic_limit_m(), 51e-9, 1e-21);
  EXPECT_DOUBLE_EQ(law.tension_N(20e-9, 20e-9), 20e-6);  // elastic: k delta
  EXPECT_DOUBLE_EQ(law.tension_N(-1e-6, 0.0), -1e-3);    // closing: elastic, no damage
  EXPECT_NEAR(law.tension_N(51e-9, 51e-9), f_max, 1e-18);
  // Half-way down the softening branch the bond carries half its peak force.
  const double half_way = 0.5 * (law.elastic_limit_m() + law.break_opening_m);
  EXPECT_NEAR(law.tension_N(half_way, half_way), 0.5 * f_max, 1e-15);
  // Damage is kept: closed to half its peak opening, it pulls with half the envelope's force.
  EXPECT_NEAR(law.tension_N(0.5 * half_way, half_way), 0.25 * f_max, 1e-15);
  EXPECT_FALSE(law.separated(0.999 * law.break_opening_m));
  EXPECT_TRUE(law.separated(law.break_opening_m));
  // Work done opening the bond monotonically to delta_f: G_f a_w (trapezoids on a fine grid).
  double work = 0, previous = 0;
  const int n = 200000;
  for (int i = 1; i <= n; ++i) {
    const double d = law.break_opening_m * i / n;
    const double f = law.tension_N(d, d);
    work += 0.5 * (f + previous) * law.break_opening_m / n;
    previous = f;
  }
  EXPECT_NEAR(work, 1.0 * a_w, 1e-4 * a_w);
}

// The case's law (make_lamella_law): F_max = strength x a_w, delta_f from G_f; a G_f that cannot reach past
// delta_0 is refused, naming the key; G_f = 0 is the brittle bond.
TEST(LamellaLaw, TheCasesLawTakesItsKeysAndRefusesAFractureEnergyBelowTheElasticOne) {
  Params p;
  p.lamella_stiffness_N_m = 1e3;
  p.lamella_strength_Pa = 1.5e6;
  p.lamella_fracture_energy_J_m2 = 1.0;
  const double a_w = 34e-12;
  const LamellaLaw law = make_lamella_law(p, a_w);
  EXPECT_DOUBLE_EQ(law.peak_force_N, 1.5e6 * a_w);
  EXPECT_DOUBLE_EQ(law.break_opening_m, 2.0 * a_w / (1.5e6 * a_w));
  // The elastic energy at the peak is F_max delta_0 / (2 a_w) = 1.5e6^2 x 34e-12 / 2e3 = 0.03825 J/m^2.
  p.lamella_fracture_energy_J_m2 = 0.038;
  try {
    make_lamella_law(p, a_w);
    FAIL() << "a fracture energy below the elastic energy at the peak was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tissue.lamella_fracture_energy_J_m2 = 0.038"), std::string::npos) << e.what();
  }
  p.lamella_fracture_energy_J_m2 = 0.039;
  EXPECT_GT(make_lamella_law(p, a_w).break_opening_m, make_lamella_law(p, a_w).elastic_limit_m());
  p.lamella_fracture_energy_J_m2 = 0;
  EXPECT_EQ(make_lamella_law(p, a_w).break_opening_m, 0.0);
}

// The work put into a bond along a path that opens, closes part way and opens past delta_f equals the
// change of its stored plus dissipated energy at every point; once separated it has dissipated G_f a_w.
TEST(LamellaLaw, StoredPlusDissipatedEnergyIsTheWorkDoneOnTheBond) {
  const double a_w = 34e-12, f_max = 51e-6;
  const LamellaLaw law{1e3, f_max, lamella_break_opening_m(1.0, a_w, f_max)};
  const double d_f = law.break_opening_m;
  std::vector<double> path;  // openings, in small steps: 0 -> 0.6 d_f -> 0.1 d_f -> -0.05 d_f -> 1.01 d_f
  const auto go = [&](double from, double to) {
    for (int i = 1; i <= 100000; ++i) path.push_back(from + (to - from) * i / 100000);
  };
  go(0, 0.6 * d_f), go(0.6 * d_f, 0.1 * d_f), go(0.1 * d_f, -0.05 * d_f), go(-0.05 * d_f, 1.01 * d_f);
  double peak = 0, work = 0, previous_opening = 0, previous_force = 0;
  for (double d : path) {
    peak = std::max(peak, d);
    const double f = law.tension_N(d, peak);
    work += 0.5 * (f + previous_force) * (d - previous_opening);
    previous_opening = d, previous_force = f;
    const double energy = law.stored_energy_J(d, peak) + law.dissipated_energy_J(peak);
    ASSERT_NEAR(energy, work, 1e-4 * a_w) << "opening " << d << ", peak " << peak;
  }
  EXPECT_NEAR(law.dissipated_energy_J(peak), 1.0 * a_w, 1e-12 * a_w);  // G_f a_w
  EXPECT_EQ(law.stored_energy_J(0.5 * d_f, peak), 0.0);
  // Closed back to half its peak, a damaged bond has dissipated part and stores the secant's energy.
  EXPECT_GT(law.dissipated_energy_J(0.6 * d_f), 0.0);
  EXPECT_NEAR(law.stored_energy_J(0.3 * d_f, 0.6 * d_f), 0.5 * law.tension_N(0.3 * d_f, 0.6 * d_f) * 0.3 * d_f, 1e-25);
  // A brittle bond keeps its spring's energy until it breaks, then has lost all of it.
  const LamellaLaw brittle{2e3, 2.1e-3, 0.0};
  EXPECT_NEAR(brittle.stored_energy_J(1.04e-6, 1.04e-6), 0.5 * 2e3 * 1.04e-6 * 1.04e-6, 1e-20);
  EXPECT_EQ(brittle.dissipated_energy_J(1.04e-6), 0.0);
  EXPECT_EQ(brittle.stored_energy_J(1.06e-6, 1.06e-6), 0.0);
  EXPECT_NEAR(brittle.dissipated_energy_J(1.06e-6), 0.5 * 2e3 * 1.06e-6 * 1.06e-6, 1e-20);
}

// The contact and bond energies are the potentials of their forces: -dE/dx of each particle, by
// central differences, is the force add_cell_contact_forces gives it (across the period too).
TEST_F(TwoPairs, TheirEnergiesAreThePotentialsOfTheirForces) {
  const auto energy = [&](const Eigen::Matrix3Xd& at) {
    const CellContactEnergy e = cell_contact_energy(at, wall_wall, bonds, law, box, {1}, peak);
    return e.contact_J + e.lamella_J;
  };
  std::vector<char> intact = {1};
  std::vector<double> peak_now = peak;
  Eigen::Matrix3Xd force = Eigen::Matrix3Xd::Zero(3, 4);
  add_cell_contact_forces(x, wall_wall, bonds, law, box, intact, peak_now, force);
  ASSERT_EQ(peak_now, peak);  // still inside its peak: the energy is a potential there
  const CellContactEnergy e = cell_contact_energy(x, wall_wall, bonds, law, box, intact, peak_now);
  EXPECT_NEAR(e.contact_J, 0.5 * 1e3 * std::pow(6e-6 - std::hypot(5e-6, 1e-6), 2), 1e-24);
  EXPECT_GT(e.lamella_J, 0.0);
  EXPECT_NEAR(e.lamella_dissipated_J, law.lamella.dissipated_energy_J(0.5e-6), 1e-24);
  const double h = 1e-10;
  for (int k = 0; k < 4; ++k)
    for (int a = 0; a < 3; ++a) {
      Eigen::Matrix3Xd plus = x, minus = x;
      plus(a, k) += h, minus(a, k) -= h;
      EXPECT_NEAR(-(energy(plus) - energy(minus)) / (2 * h), force(a, k), 1e-6 * force.cwiseAbs().maxCoeff())
          << "particle " << k << ", axis " << a;
    }
}

// The quasi-static preconditioner's stiffness of the contacts and lamella is minus the derivative of their
// forces (central differences, to 1e-6), less the contact's sideways part -k_c (g - r) / r (I - n n^T),
// which it leaves out; a bond on its secant branch (damaged before) and a pair across the period included.
// A pair that the pattern does not join is counted and left out.
TEST_F(TwoPairs, TheirStiffnessIsMinusTheDerivativeOfTheirForcesLessTheContactsSidewaysPart) {
  const std::vector<char> intact = {1};
  const auto forces = [&](const Eigen::Matrix3Xd& at) {
    std::vector<char> intact_now = intact;
    std::vector<double> peak_now = peak;
    Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, 4);
    add_cell_contact_forces(at, wall_wall, bonds, law, box, intact_now, peak_now, f);
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(f.data(), f.size()));
  };
  BlockStiffness K(4, {{0, 1}, {2, 3}});
  EXPECT_EQ(add_cell_contact_stiffness(x, wall_wall, bonds, law, box, intact, peak, K), 0);
  Eigen::MatrixXd stiffness = Eigen::MatrixXd(K.matrix());
  EXPECT_LT((stiffness - stiffness.transpose()).cwiseAbs().maxCoeff(), 1e-12 * stiffness.cwiseAbs().maxCoeff());
  // The contact's sideways part, which the exact derivative has.
  const Eigen::Vector3d d = x.col(0) - x.col(1);
  const double r = d.norm();
  const Eigen::Matrix3d sideways = -1e3 * (6e-6 - r) / r * (Eigen::Matrix3d::Identity() - d * d.transpose() / (r * r));
  Eigen::MatrixXd exact = stiffness;
  exact.block<3, 3>(0, 0) += sideways, exact.block<3, 3>(3, 3) += sideways;
  exact.block<3, 3>(0, 3) -= sideways, exact.block<3, 3>(3, 0) -= sideways;
  const double h = 1e-11;
  for (int j = 0; j < 12; ++j) {
    Eigen::Matrix3Xd plus = x, minus = x;
    plus(j % 3, j / 3) += h, minus(j % 3, j / 3) -= h;
    const Eigen::VectorXd fd = -(forces(plus) - forces(minus)) / (2 * h);
    EXPECT_LT((exact.col(j) - fd).cwiseAbs().maxCoeff(), 1e-6 * exact.cwiseAbs().maxCoeff()) << "column " << j;
  }
  EXPECT_NEAR(d.dot(stiffness.block<3, 3>(0, 0) * d) / (r * r), 1e3, 1e-9);  // k_c along the line

  BlockStiffness bonds_only(4, {{2, 3}});
  EXPECT_EQ(add_cell_contact_stiffness(x, wall_wall, bonds, law, box, intact, peak, bonds_only), 1);
  const Eigen::MatrixXd without_contact = Eigen::MatrixXd(bonds_only.matrix());
  EXPECT_EQ(without_contact.topLeftCorner(6, 6).norm(), 0.0);
}

TEST(LamellaLaw, ABondThatSoftensPullsBothWallsEquallyAndSeparatesAtItsBreakOpening) {
  // One bond at rest 6 um, opened step by step: the force on each end is equal and opposite; it
  // stays intact up to delta_f and is gone beyond it.
  CellContactLaw law{6e-6, 1e3, LamellaLaw{1e3, 51e-6, 1.0e-6}};
  const std::vector<LamellaBond> bonds = {{0, 1, 6e-6}};
  std::vector<char> intact = {1};
  std::vector<double> peak = {0.0};
  const PairList no_contact{{0, 0, 0}, {}, 0, 0};
  Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, 2);
  for (double opening : {0.02e-6, 0.3e-6, 0.6e-6, 0.99e-6}) {
    x.col(1) = Eigen::Vector3d(0, 0, 6e-6 + opening);
    Eigen::Matrix3Xd force = Eigen::Matrix3Xd::Zero(3, 2);
    EXPECT_EQ(add_cell_contact_forces(x, no_contact, bonds, law, PeriodicBox{}, intact, peak, force), 0) << opening;
    EXPECT_EQ(force.col(0), -force.col(1));
    EXPECT_NEAR(force(2, 0), law.lamella.tension_N(opening, opening), 1e-18) << opening;
    EXPECT_GT(force(2, 0), 0.0);  // pulls 0 toward 1 (+z)
  }
  x.col(1) = Eigen::Vector3d(0, 0, 7.01e-6);
  Eigen::Matrix3Xd force = Eigen::Matrix3Xd::Zero(3, 2);
  EXPECT_EQ(add_cell_contact_forces(x, no_contact, bonds, law, PeriodicBox{}, intact, peak, force), 1);
  EXPECT_EQ(intact[0], 0);
  EXPECT_EQ(force.norm(), 0.0);
}

TEST(Tissue, InterpenetratingWallsStopTheRunNamingBothCells) {
  Params p = tissue_case(2, 1, 1);
  Simulation sim(p, build_tissue(p));
  EXPECT_NO_THROW(sim.check_containment());
  const CellRanges& cells = sim.cells();
  State& s = sim.mutable_state();
  // The wall particle of cell 1 nearest cell 0's centre, pushed 10 um toward it: through the 6 um gap
  // and 4 um into cell 0.
  const Eigen::Vector3d centre0 = s.fluid.x.leftCols(cells.fluid_count(0)).rowwise().mean();
  Eigen::Index nearest = cells.wall[1];
  for (Eigen::Index k = cells.wall[1]; k < cells.wall[2]; ++k)
    if ((s.wall.x.col(k) - centre0).norm() < (s.wall.x.col(nearest) - centre0).norm()) nearest = k;
  s.wall.x.col(nearest) += 10e-6 * (centre0 - s.wall.x.col(nearest)).normalized();
  try {
    sim.check_containment();
    FAIL() << "no failure";
  } catch (const NumericalFailure& e) {
    const std::string what = e.what();
    // Either wall may be found in the other first: the moved particle drags its triangles along.
    EXPECT_TRUE(what.find(" of cell 1 is inside cell 0") != std::string::npos ||
                what.find(" of cell 0 is inside cell 1") != std::string::npos)
        << what;
    EXPECT_NE(what.find("the walls interpenetrate"), std::string::npos) << what;
  }
}

// Per-cell sums (wall pressure, closure, Eq 11) cut at the cells' ends within the threads' blocks: the
// same bytes twice on two threads, and one thread's result to round-off.
TEST(Tissue, TwoThreadsRepeatAndAgreeWithOne) {
  Params p = tissue_case(2, 1, 1);
  const Tissue tissue = build_tissue(p);
  const auto run = [&](int threads) {
    Simulation sim(p, tissue);
    sim.set_threads(threads);
    for (int n = 0; n < 30; ++n) sim.step();
    return sim.state();
  };
  const State one = run(1), two = run(2), again = run(2);
  EXPECT_EQ(two.fluid.x, again.fluid.x);
  EXPECT_EQ(two.fluid.m, again.fluid.m);
  EXPECT_EQ(two.wall.x, again.wall.x);
  EXPECT_LT((two.fluid.x - one.fluid.x).cwiseAbs().maxCoeff(), 1e-12 * p.diameter_m);
  EXPECT_LT((two.wall.x - one.wall.x).cwiseAbs().maxCoeff(), 1e-12 * p.diameter_m);
  EXPECT_LT(((two.fluid.m - one.fluid.m).array() / one.fluid.m.array()).abs().maxCoeff(), 1e-12);
  EXPECT_GT((one.fluid.x - tissue.fluid_x).cwiseAbs().maxCoeff(), 0.0);  // the particles moved
}
