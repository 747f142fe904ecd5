// Per-pair terms: Newton's third law (Tables 1-2, Eqs 3, 4, 12-19), LJ shape (model.md §4),
// mass transfer direction (Eq 11).
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/neighbours.hpp"
#include "physics/drying.hpp"
#include "physics/eos.hpp"
#include "physics/fluid_pairs.hpp"
#include "physics/kernel.hpp"
#include "physics/lennard_jones.hpp"
#include "physics/mass_transfer.hpp"
#include "physics/wall_terms.hpp"

using namespace cellsim;

TEST(PairTerms, ThePairLoopGivesEqs3And4And10EqualAndOpposite) {
  // Two fluid particles through the solver's own pair loop (fluid_pairs.cpp), against Eqs 3, 4
  // and 10 written out here: F_i = -m_i m_j (P_i/rho_i^2 + P_j/rho_j^2) g x_ij
  // + m_i m_j (2 mu)/(rho_i rho_j) g v_ij, F_j = -F_i, with g = (1/r) dW/dr.
  FluidParticles f;
  f.x.resize(3, 2);
  f.x << 0, 3e-6, 0, -1e-6, 0, 2e-6;
  f.v.resize(3, 2);
  f.v << 0.2, 0, 0.1, 0, -0.3, 0;
  f.m = Eigen::Vector2d(5.7e-13, 6.1e-13);
  f.rho = Eigen::Vector2d(1001, 998);
  const EquationOfState eos{2e5, 20e6, 1000, 7};
  const double mu = 0.1;
  const CubicSplineKernel kernel(6.8e-6);
  NeighbourLists lists(1e-6);
  lists.update(f.x, Eigen::Matrix3Xd(3, 0), kernel.support(), 0.0);
  FluidRates rates;
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, mu, 1, rates);

  const Eigen::Vector3d xij = f.x.col(0) - f.x.col(1), vij = f.v.col(0) - f.v.col(1);
  const double g = kernel.dW_dr_over_r(xij.norm());
  const double Pi = eos.pressure(f.rho[0]), Pj = eos.pressure(f.rho[1]);
  const Eigen::Vector3d expected =
      -f.m[0] * f.m[1] * (Pi / (f.rho[0] * f.rho[0]) + Pj / (f.rho[1] * f.rho[1])) * g * xij +
      f.m[0] * f.m[1] * 2 * mu / (f.rho[0] * f.rho[1]) * g * vij;
  EXPECT_TRUE(rates.force.col(0).isApprox(expected, 1e-12)) << rates.force.col(0).transpose() << " vs " << expected.transpose();
  EXPECT_TRUE((rates.force.col(0) + rates.force.col(1)).isZero(1e-12 * expected.norm()));
  EXPECT_NEAR(rates.drho_dt[0], f.m[1] * vij.dot(g * xij), 1e-12 * std::abs(rates.drho_dt[0]));
  EXPECT_NEAR(rates.drho_dt[1], f.m[0] * vij.dot(g * xij), 1e-12 * std::abs(rates.drho_dt[1]));
  EXPECT_NEAR(rates.pressure[0], Pi, 1e-9);
  // Positive pressure pushes the pair apart; viscosity alone (K = 0, P_T = 0) opposes v_ij.
  const EquationOfState no_pressure{0.0, 0.0, 1000, 7};
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, no_pressure, mu, 1, rates);
  EXPECT_LT(rates.force.col(0).dot(vij), 0.0);
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, 0.0, 1, rates);
  EXPECT_GT(rates.force.col(0).dot(xij), 0.0);
}

TEST(PairTerms, EquationOfStateIsEq7) {
  // P = P_T + K [(rho/rho0)^7 - 1]: P_T at rho0, and the integer power agrees with std::pow.
  const EquationOfState eos{2e5, 20e6, 1000, 7};
  EXPECT_EQ(eos.pressure(1000), 2e5);
  EXPECT_NEAR(eos.pressure(1010), 2e5 + 20e6 * (std::pow(1.01, 7) - 1), 1e-6);
  EXPECT_NEAR(eos.pressure(990), 2e5 + 20e6 * (std::pow(0.99, 7) - 1), 1e-6);
  const EquationOfState other{1e5, 20e6, 1000, 5};
  EXPECT_NEAR(other.pressure(1010), 1e5 + 20e6 * (std::pow(1.01, 5) - 1), 1e-6);
  EXPECT_NEAR(eos.sound_speed_m_s(), std::sqrt(7 * 20e6 / 1000), 1e-9);  // c0 of the CFL limit
}

TEST(PairTerms, BondDampingIsEqualAndOppositeAndOpposesMotion) {
  const Eigen::Vector3d vk(1, 2, 3), vj(-1, 0, 2);
  const Eigen::Vector3d f_k = wall::damping_force(5e-6, vk, vj), f_j = wall::damping_force(5e-6, vj, vk);
  EXPECT_TRUE((f_k + f_j).isZero(0.0));
  EXPECT_LT(f_k.dot(vk - vj), 0.0);
}

TEST(PairTerms, StiffAndContractionTensions) {
  // Eq 15: zero at rest, tension when stretched, compression when shortened.
  EXPECT_EQ(wall::stiff_tension(18e6, 6e-6, 6e-6, 6e-6), 0.0);
  const double stretched = wall::stiff_tension(18e6, 6e-6, 6e-6, 6.6e-6);
  EXPECT_NEAR(stretched, 18e6 * 6e-6 * 6e-6 / std::sqrt(3.0) * (1.1 - 1 / 1.1), 1e-15);
  EXPECT_LT(wall::stiff_tension(18e6, 6e-6, 6e-6, 5e-6), 0.0);
  // Eq 21: L_ref = l0 [1 - c (1 - X)]; fresh keeps l0, dried shortens it, the ramp interpolates.
  EXPECT_EQ(wall::contraction_rest_length(6e-6, 0.4, 1.0, 1.0), 6e-6);
  EXPECT_NEAR(wall::contraction_rest_length(6e-6, 0.4, 0.1, 1.0), 6e-6 * 0.64, 1e-18);
  EXPECT_EQ(wall::contraction_rest_length(6e-6, 0.4, 0.1, 0.0), 6e-6);
  EXPECT_NEAR(wall::contraction_tension(1e4, 6e-6, 0.64 * 6e-6), 1e4 * 0.36 * 6e-6, 1e-15);
  // Smoothstep ramp: 0, 1/2, 1 with zero slope at both ends.
  EXPECT_EQ(drying::smoothstep_ramp(0, 20e-6), 0.0);
  EXPECT_NEAR(drying::smoothstep_ramp(10e-6, 20e-6), 0.5, 1e-15);
  EXPECT_EQ(drying::smoothstep_ramp(25e-6, 20e-6), 1.0);
  EXPECT_LT(drying::smoothstep_ramp(0.2e-6, 20e-6), 1e-3);
}

TEST(PairTerms, TurgorFollowsTheDryingRampFromFreshToItsDrynessValue) {
  // model.md §5: P_T0 at the start of drying (the settled fresh cell), P_T0 X once the ramp is done.
  EXPECT_EQ(drying::turgor_Pa(200e3, 0.1, 0.0), 200e3);
  EXPECT_NEAR(drying::turgor_Pa(200e3, 0.1, 1.0), 20e3, 1e-9);
  EXPECT_NEAR(drying::turgor_Pa(200e3, 0.1, 0.5), 110e3, 1e-9);
  EXPECT_EQ(drying::turgor_Pa(200e3, 1.0, 0.7), 200e3);  // a fresh cell keeps its turgor throughout
}

TEST(PairTerms, LennardJonesShape) {
  const LennardJones lj{8e-6, 13.6e-6, 5e-12, 1e-11};
  const auto force_on_fluid = [&](double r) { return lj.f_of_r2(r * r) * r; };  // along x_ik, magnitude
  EXPECT_EQ(force_on_fluid(8e-6), 0.0);                                        // zero at r0
  for (double r : {3e-6, 5e-6, 7.9e-6}) EXPECT_GT(force_on_fluid(r), 0.0) << r;  // repulsive below r0
  for (double r : {8.1e-6, 10e-6, 13.5e-6}) EXPECT_LT(force_on_fluid(r), 0.0) << r;  // attractive to r_c
  for (double r : {13.6e-6, 20e-6}) EXPECT_EQ(force_on_fluid(r), 0.0) << r;      // zero beyond
  // Eq 18 value: f0 [(r0/r)^8 - (r0/r)^4] / r^2 at r = r0 / 2.
  const double r = 4e-6;
  EXPECT_NEAR(lj.f_of_r2(r * r), 5e-12 * (256.0 - 16.0) / (r * r), 1e-9);
}

TEST(PairTerms, MassLeavesUnderExcessPressureAndEntersBelow) {
  const double area = 7e-8, Lp = 2.5e-6, rho = 1000, osmotic = -2e5;
  EXPECT_LT(mass_rate(area, Lp, rho, 3082, 2.5e5, osmotic), 0.0);  // P + Pi > 0: water leaves
  EXPECT_GT(mass_rate(area, Lp, rho, 3082, 1.5e5, osmotic), 0.0);  // P + Pi < 0: water enters
  EXPECT_EQ(mass_rate(area, Lp, rho, 3082, 2.0e5, osmotic), 0.0);
  EXPECT_NEAR(mass_rate(area, Lp, rho, 3082, 2.5e5, osmotic), -(area * Lp * rho / 3082) * 5e4, 1e-25);
  // Eq 9: mass change alone changes density in proportion (particle volume m/rho unchanged).
  EXPECT_NEAR(density_rate(0.0, 1000, 5e-13, 5e-14), 1000 * 0.1, 1e-9);
}
