// Heterogeneous properties (heterogeneity.hpp, docs/model.md §3c): lognormal factors of mean 1 and the
// asked coefficient of variation, correlated over the asked length, the same bits from the same seed,
// and a cell that runs with them keeps its energy account.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "engine/simulation.hpp"
#include "engine/sph_fluid.hpp"
#include "geometry/heterogeneity.hpp"
#include "geometry/tissue.hpp"
#include "small_cell.hpp"

using namespace cellsim;

namespace {

struct Moments {
  double mean, sd;
};
Moments moments(const std::vector<double>& v) {
  const double mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  double var = 0;
  for (double x : v) var += (x - mean) * (x - mean);
  return {mean, std::sqrt(var / static_cast<double>(v.size() - 1))};
}

}  // namespace

TEST(Heterogeneity, StandardNormalsAreSeededAndStandard) {
  const auto a = standard_normals(3, 1, 200000), b = standard_normals(3, 1, 200000);
  EXPECT_EQ(a, b);  // the same seed and stream: the same bits
  EXPECT_NE(a, standard_normals(4, 1, 200000));
  EXPECT_NE(a, standard_normals(3, 2, 200000));
  const Moments m = moments(a);
  EXPECT_NEAR(m.mean, 0.0, 4.0 / std::sqrt(200000.0));  // four standard errors
  EXPECT_NEAR(m.sd, 1.0, 0.01);
}

TEST(Heterogeneity, LognormalFactorsHaveMeanOneAndTheAskedVariation) {
  const auto z = standard_normals(11, 1, 400000);
  for (double cv : {0.1, 0.3, 0.6}) {
    std::vector<double> f;
    for (double x : z) f.push_back(lognormal_factor(x, cv));
    const Moments m = moments(f);
    EXPECT_NEAR(m.mean, 1.0, 4.0 * cv / std::sqrt(400000.0)) << "cv " << cv;
    EXPECT_NEAR(m.sd / m.mean, cv, 0.03 * cv) << "cv " << cv;
    EXPECT_GT(*std::min_element(f.begin(), f.end()), 0.0);  // a modulus or a thickness stays positive
  }
  EXPECT_EQ(lognormal_factor(2.5, 0.0), 1.0);
}

TEST(Heterogeneity, SmoothedNoiseKeepsUnitVarianceAndIsCorrelatedOverItsLength) {
  // A square of points at a quarter of the length apart; the correlation of Gaussian-smoothed white
  // noise at distance d is exp(-d^2 / (4 length^2)): 0.78 at one length, 0.21 at 2.5.
  const double length = 1.0, spacing = 0.25;
  const int side = 24;
  Eigen::Matrix3Xd points(3, side * side);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) points.col(i * side + j) = Eigen::Vector3d(i * spacing, j * spacing, 0);
  const std::vector<int> group(static_cast<std::size_t>(side * side), 0);
  const int centre = (side / 2) * side + side / 2, one_length = centre + 4 * side, far = centre + 10;
  std::vector<double> at_centre, at_one, at_far;
  for (int seed = 1; seed <= 200; ++seed) {
    const auto field = correlated_normals(standard_normals(seed, 1, points.cols()), points, group, length);
    at_centre.push_back(field[centre]);
    at_one.push_back(field[one_length]);
    at_far.push_back(field[far]);
  }
  const auto correlation = [&](const std::vector<double>& a, const std::vector<double>& b) {
    double ab = 0, aa = 0, bb = 0;
    for (std::size_t k = 0; k < a.size(); ++k) ab += a[k] * b[k], aa += a[k] * a[k], bb += b[k] * b[k];
    return ab / std::sqrt(aa * bb);
  };
  EXPECT_NEAR(moments(at_centre).sd, 1.0, 0.15);  // 200 draws: a standard error of 0.05
  EXPECT_NEAR(correlation(at_centre, at_one), std::exp(-0.25), 0.08);
  EXPECT_NEAR(correlation(at_centre, at_far), std::exp(-1.5625), 0.15);
  // Points of another group (another cell's wall) do not mix in.
  std::vector<int> split = group;
  for (int k = 0; k < side * side / 2; ++k) split[static_cast<std::size_t>(k)] = 1;
  const auto white = standard_normals(5, 1, points.cols());
  const auto whole = correlated_normals(white, points, group, length);
  const auto halves = correlated_normals(white, points, split, length);
  EXPECT_NE(whole[side * side / 2], halves[side * side / 2]);  // at the seam: its neighbours are gone
  EXPECT_EQ(correlated_normals(white, points, group, 0.0), white);
}

TEST(Heterogeneity, ACellsBondsGetTheirFactorsAndItsFluidItsViscosity) {
  Params p = cellsim::testing::small_cell_case(
      {{"heterogeneity", {{"seed", 5}, {"wall_G_cv", 0.3}, {"wall_thickness_cv", 0.2}, {"fluid_viscosity_cv", 0.5}}}});
  const Tissue tissue = build_tissue(p);
  const Simulation sim(p, tissue);
  const BondLaw& law = sim.bond_law();
  std::vector<double> G_t_factor;
  for (double G_t : law.G_t_N_m) G_t_factor.push_back(G_t / (p.G_Pa * p.thickness_m));
  const Moments m = moments(G_t_factor);  // the product of two independent factors: cv^2 = 1.3^2 1.2^2 / 1 - 1
  EXPECT_NEAR(m.mean, 1.0, 0.06);
  EXPECT_NEAR(m.sd, std::sqrt(1.09 * 1.04 - 1.0), 0.06);
  const Viscosity mu = dynamic_cast<const SphFluid&>(sim.fluid()).viscosity();
  ASSERT_NE(mu.per_particle_Pa_s, nullptr);
  for (Eigen::Index i = 0; i < sim.state().fluid.size(); ++i)
    EXPECT_EQ(mu.per_particle_Pa_s[i], mu.per_particle_Pa_s[0]);  // one cell, one viscosity
  EXPECT_NE(mu.per_particle_Pa_s[0], p.viscosity_Pa_s);
  // Uniform unless asked: factors of exactly 1.
  Params uniform = cellsim::testing::small_cell_case();
  const Tissue t2 = build_tissue(uniform);
  const Simulation plain(uniform, t2);
  for (double G_t : plain.bond_law().G_t_N_m) EXPECT_EQ(G_t, uniform.G_Pa * uniform.thickness_m);
  EXPECT_EQ(dynamic_cast<const SphFluid&>(plain.fluid()).viscosity().per_particle_Pa_s, nullptr);
}

TEST(Heterogeneity, TheSameSeedGivesTheSameBitsAndTheAccountHolds) {
  const auto run = [](int seed, double cv) {
    Params p = cellsim::testing::small_cell_case({{"heterogeneity",
                                                  {{"seed", seed},
                                                   {"wall_G_cv", cv},
                                                   {"wall_thickness_cv", 0.75 * cv},
                                                   {"fluid_viscosity_cv", cv},
                                                   {"correlation_length_um", 8}}}});
    const Tissue tissue = build_tissue(p);
    Simulation sim(p, tissue);
    for (int n = 0; n < 2000; ++n) sim.step();
    return std::make_pair(sim.state().wall.x, sim.record());
  };
  const auto [x1, r1] = run(1, 0.4);
  const auto [x1_again, r1_again] = run(1, 0.4);
  const auto [x2, r2] = run(2, 0.4);
  const auto [x_uniform, r_uniform] = run(1, 0.0);
  EXPECT_EQ(x1, x1_again);
  EXPECT_NE(x1, x2);
  EXPECT_NE(x1, x_uniform);
  // The cell as built rings (no settle here): its account's residual is that of the uniform cell, a
  // fraction of a percent of the stored energy, whatever the properties' spread.
  EXPECT_LT(std::abs(r1.energy_residual_J), 1e-2 * r1.stored_energy_J);
  EXPECT_LT(std::abs(r1.energy_residual_J), 1.5 * std::abs(r_uniform.energy_residual_J));
}
