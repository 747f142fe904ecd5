// Per-pair terms: Newton's third law (Tables 1-2, Eqs 3, 4, 12-19), LJ shape (model.md §4),
// mass transfer direction (Eq 11).
#include <gtest/gtest.h>

#include "drying.hpp"
#include "lennard_jones.hpp"
#include "mass_transfer.hpp"
#include "sph_terms.hpp"
#include "wall_terms.hpp"

using namespace cellsim;

TEST(PairTerms, PressureAndViscousForcesAreEqualAndOpposite) {
  const double mi = 5.7e-13, mj = 6.1e-13, rhoi = 1001, rhoj = 998, Pi = 2.1e5, Pj = 1.9e5;
  const Eigen::Vector3d xij(3e-6, -1e-6, 2e-6), vij(0.2, 0.1, -0.3);
  const double g = -1.7e20;  // (1/r) dW/dr at |xij|: symmetric in i and j
  const Eigen::Vector3d p_ij = sph::pressure_force(mi, mj, Pi / (rhoi * rhoi), Pj / (rhoj * rhoj), g, xij);
  const Eigen::Vector3d p_ji = sph::pressure_force(mj, mi, Pj / (rhoj * rhoj), Pi / (rhoi * rhoi), g, -xij);
  EXPECT_TRUE((p_ij + p_ji).isZero(1e-12 * p_ij.norm()));
  EXPECT_GT(p_ij.dot(xij), 0.0);  // positive pressure pushes the pair apart
  const Eigen::Vector3d v_ij = sph::viscous_force(0.2, mi / rhoi, mj / rhoj, g, vij);
  const Eigen::Vector3d v_ji = sph::viscous_force(0.2, mj / rhoj, mi / rhoi, g, -vij);
  EXPECT_TRUE((v_ij + v_ji).isZero(1e-12 * v_ij.norm()));
  EXPECT_LT(v_ij.dot(vij), 0.0);  // viscosity opposes the relative velocity
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
