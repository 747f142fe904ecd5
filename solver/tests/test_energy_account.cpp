// The energy account (engine/energy_account.hpp, docs/model.md): each stored energy is the potential of
// its force (its derivative, by central differences, is the force law the step uses), and over a run
// the stored energy changes by what the plates, losses, mass transfer and the drying ramp put in: the
// residual stays a small fraction of the energy that flowed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "engine/simulation.hpp"
#include "geometry/tissue.hpp"
#include "io/compression_summary.hpp"
#include "io/drying_summary.hpp"
#include "physics/eos.hpp"
#include "physics/lennard_jones.hpp"
#include "physics/plates.hpp"
#include "physics/wall_terms.hpp"
#include "small_cell.hpp"

using namespace cellsim;

namespace {

// Central difference of f at x with step h.
template <class F>
double derivative(F&& f, double x, double h) {
  return (f(x + h) - f(x - h)) / (2.0 * h);
}

}  // namespace

TEST(EnergyAccount, InternalEnergyIsTheWorkOfTheEquationOfState) {
  for (const double turgor : {0.0, 2e5, 2e6}) {
    const EquationOfState eos{turgor, 20e6, 1000, 7};
    EXPECT_DOUBLE_EQ(eos.internal_energy_J_kg(1000), 0.0);
    for (const double rho : {980.0, 1000.0, 1003.0, 1020.0}) {
      const double de_drho = derivative([&](double r) { return eos.internal_energy_J_kg(r); }, rho, 1e-3);
      const double P_over_rho2 = eos.pressure(rho) / (rho * rho);
      EXPECT_NEAR(de_drho, P_over_rho2, 1e-6 * std::abs(P_over_rho2) + 1e-9) << turgor << " Pa, rho " << rho;
      // e is linear in P_T: a large step differentiates exactly, without cancelling round-off.
      const double de_dPT = (EquationOfState{turgor + 1e4, 20e6, 1000, 7}.internal_energy_J_kg(rho) -
                             eos.internal_energy_J_kg(rho)) / 1e4;
      EXPECT_NEAR(de_dPT, eos.internal_energy_per_turgor(rho), 1e-9 * std::abs(de_dPT) + 1e-18);
      const double enthalpy = eos.internal_energy_J_kg(rho) + eos.pressure(rho) / rho;
      EXPECT_NEAR(eos.enthalpy()(rho), enthalpy, 1e-12 * std::abs(eos.pressure(rho) / rho));
    }
  }
  const EquationOfState gamma3{2e5, 20e6, 1000, 3};  // the general exponent's branch
  EXPECT_NEAR(derivative([&](double r) { return gamma3.internal_energy_J_kg(r); }, 1010, 1e-3),
              gamma3.pressure(1010) / (1010.0 * 1010.0), 1e-6 * gamma3.pressure(1010) / (1010.0 * 1010.0));
  EXPECT_NEAR(gamma3.enthalpy()(1010), gamma3.internal_energy_J_kg(1010) + gamma3.pressure(1010) / 1010,
              1e-12 * gamma3.pressure(1010) / 1010);
}

TEST(EnergyAccount, WallSpringEnergiesAreThePotentialsOfTheirTensions) {
  const double G = 18e6, t0 = 6e-6, l0 = 4e-6, k = 1e4, l_ref = 3.2e-6;
  EXPECT_DOUBLE_EQ(wall::stiff_energy(G, t0, l0, l0), 0.0);
  for (const double l : {2.5e-6, 3.9e-6, 4e-6, 4.4e-6, 6e-6}) {
    const double tension = wall::stiff_tension(G, t0, l0, l);
    EXPECT_NEAR(derivative([&](double x) { return wall::stiff_energy(G, t0, l0, x); }, l, 1e-10), tension,
                1e-6 * std::abs(tension) + 1e-9)
        << l;
    EXPECT_NEAR(derivative([&](double x) { return wall::contraction_energy(k, x, l_ref); }, l, 1e-10),
                wall::contraction_tension(k, l, l_ref), 1e-6 * std::abs(wall::contraction_tension(k, l, l_ref)));
  }
}

TEST(EnergyAccount, LennardJonesPotentialGivesItsForceIsContinuousAndVanishesAtTheCutoff) {
  const LennardJones lj{8e-6, 13.6e-6, 5e-12, 1e-11};
  for (const double r : {5e-6, 7e-6, 7.9e-6, 8.1e-6, 10e-6, 13e-6}) {
    const double minus_dphi_dr = -derivative([&](double x) { return lj.potential_J(x * x); }, r, 1e-11);
    const double force = lj.f_of_r2(r * r) * r;  // F = f(r) x_ik, |x_ik| = r
    EXPECT_NEAR(minus_dphi_dr, force, 1e-5 * std::abs(force)) << r;
  }
  const double below = lj.potential_J(std::pow(8e-6 * (1 - 1e-9), 2));
  const double above = lj.potential_J(std::pow(8e-6 * (1 + 1e-9), 2));
  EXPECT_NEAR(below, above, 1e-6 * std::abs(above));  // continuous where the strength changes
  EXPECT_LT(above, 0.0);                              // the attraction's well
  EXPECT_NEAR(lj.potential_J(std::pow(13.6e-6 * (1 - 1e-9), 2)), 0.0, 1e-7 * std::abs(above));
  EXPECT_EQ(lj.potential_J(std::pow(14e-6, 2)), 0.0);
}

TEST(EnergyAccount, PlateEnergyIsThePotentialOfEquation22) {
  const PlateLaw law{3e-6, 1e3, 150e-6, 150e-6};
  Plates plates;
  plates.active = true;
  plates.top_z_m = 10e-6;
  plates.bottom_z_m = -10e-6;
  const auto energy = [&](double z) {
    Eigen::Matrix3Xd x(3, 1);
    x << 0, 0, z;
    return plate_energy_J(x, law, plates);
  };
  for (const double z : {8e-6, 9.5e-6, -8.5e-6}) {
    Eigen::Matrix3Xd x(3, 1), force = Eigen::Matrix3Xd::Zero(3, 1);
    x << 0, 0, z;
    add_plate_forces(x, law, plates, force);
    EXPECT_NEAR(-derivative(energy, z, 1e-10), force(2, 0), 1e-6 * std::abs(force(2, 0))) << z;
  }
  EXPECT_EQ(energy(0.0), 0.0);  // out of both plates' range
}

// A whole run of the small cell, dried to X/X0 = 0.5 (the ramp drives it) and compressed: the stored
// energy changes by what flowed in, to a small fraction of each flow; with delta-SPH as well, its flow
// counted; for both couplings, each with its density update (lennard_jones: kick; pressure: drift).
class EnergyAccountRun : public ::testing::TestWithParam<std::tuple<std::string, double>> {};
INSTANTIATE_TEST_SUITE_P(CouplingAndDensityDiffusion, EnergyAccountRun,
                         ::testing::Combine(::testing::Values("lennard_jones", "pressure"), ::testing::Values(0.0, 0.1)));

TEST_P(EnergyAccountRun, ResidualOfADryingAndACompressionIsSmallAgainstWhatFlowed) {
  const auto& [coupling, diffusion] = GetParam();
  Params p = cellsim::testing::small_cell_case({{"drying", {{"dryness", 0.5}, {"ramp_time_us", 2}}},
                                                {"fluid", {{"density_diffusion", diffusion}}},
                                                {"coupling", {{"model", coupling}}}});
  const Tissue cell = build_tissue(p);
  Simulation sim(p, cell);
  for (int n = 0; n < 8000; ++n) sim.step();  // 4 us: the ramp and its settling
  const Record dried = sim.record();
  EXPECT_GT(dried.energy[kDrive], 0.0);
  EXPECT_GT(dried.energy[kViscousLoss], 0.0);
  EXPECT_GT(dried.energy[kDampingLoss], 0.0);
  EXPECT_LT(std::abs(dried.energy_residual_J), 0.01 * dried.energy[kDrive])
      << "drive " << dried.energy[kDrive] << " J, residual " << dried.energy_residual_J << " J";
  sim.start_compression();
  for (int n = 0; n < 8000; ++n) sim.step();  // 4 us at 1 m/s: 4 um of plate travel
  const Record pressed = sim.record();
  const double work = pressed.energy[kPlateWork] - dried.energy[kPlateWork];
  ASSERT_GT(work, 0.0);
  EXPECT_LT(std::abs(pressed.energy_residual_J - dried.energy_residual_J), 0.01 * work)
      << "plate work " << work << " J, residual change " << pressed.energy_residual_J - dried.energy_residual_J;
  if (diffusion > 0) EXPECT_NE(pressed.energy[kDensityDiffusion], 0.0);
  else EXPECT_EQ(pressed.energy[kDensityDiffusion], 0.0);
}

// A stack of two small cells compressed: the plates press the cells' walls together and load the middle
// lamella between them. Their contact and bond energies (and what the lamella dissipates) are in the
// account, so its residual stays a small fraction of the plate work; they are themselves more than that
// fraction, so an account without them would not balance.
TEST(EnergyAccount, ATissuesContactsAndMiddleLamellaAreInTheAccount) {
  Params p = cellsim::testing::small_cell_case({{"tissue", {{"cells_z", 2}, {"wall_gap_um", 1.6}}},
                                                {"coupling", {{"repulsion_f0_N_m", 1.5e-11}}},
                                                {"compression", {{"plate_speed_m_s", 5.0}}}});
  const Tissue tissue = build_tissue(p);
  Simulation sim(p, tissue);
  for (int n = 0; n < 2000; ++n) sim.step();
  const Record rest = sim.record();
  sim.start_compression();
  for (int n = 0; n < 8000; ++n) sim.step();
  const Record pressed = sim.record();
  const double work = pressed.energy[kPlateWork] - rest.energy[kPlateWork];
  ASSERT_GT(work, 0.0);
  const double between = pressed.energy[kContact] + pressed.energy[kLamella] + pressed.energy[kLamellaLoss] -
                         rest.energy[kContact] - rest.energy[kLamella] - rest.energy[kLamellaLoss];
  // Measured: 4.6 nJ of work, 1.09 nJ taken by the lamella's bonds as they separate, residual 7 pJ.
  EXPECT_LT(std::abs(pressed.energy_residual_J - rest.energy_residual_J), 0.01 * work)
      << "plate work " << work << " J, residual change " << pressed.energy_residual_J - rest.energy_residual_J;
  EXPECT_GT(std::abs(between), 0.05 * work) << "contact, lamella and its loss changed by " << between << " J";
}

// A stage whose residual passes kEnergyResidualTolerance of the energy through it is warned, naming its
// share: a drying's over the magnitudes of its flows and losses, a compression's over the plate work.
TEST(EnergyAccount, AStageWhoseResidualPassesTheToleranceIsWarnedWithItsShare) {
  EnergyValues terms{};
  terms[kDrive] = 3e-6;
  terms[kPeriodLoss] = 1e-6;  // a loss counts by its magnitude too
  EXPECT_DOUBLE_EQ(residual_over_flows(terms, -1e-7), -0.025);
  EXPECT_TRUE(std::isnan(residual_over_flows(EnergyValues{}, 0.0)));  // nothing flowed: no share

  DryingSummary drying;
  drying.steady = true;
  drying.energy_residual_share = -0.025;
  EXPECT_NE(drying.warning().find("energy account: drying's residual is -2.5 % of the energy that flowed"),
            std::string::npos) << drying.warning();
  drying.energy_residual_share = 0.5 * kEnergyResidualTolerance;
  EXPECT_EQ(drying.warning(), "");
  drying.energy_residual_share = std::nan("");  // no drying ran
  EXPECT_EQ(drying.warning(), "");

  CompressionSummary compression{true, "compression.end_strain = 0.12", true, 1000, 0.12, 0.03};
  EXPECT_EQ(compression.warning(), "energy account: compression's residual is 3 % of the plate work (tolerance 2 %)");
  compression.reached = false;  // capped too: both, the cap first (the report sorts them by their start)
  EXPECT_EQ(compression.warning().find("compression reached compression.steps = 1000"), 0u);
  EXPECT_NE(compression.warning().find("; energy account: compression's residual is 3 %"), std::string::npos);
}
