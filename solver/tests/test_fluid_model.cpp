// The fluid's room (engine/fluid_model.hpp): what the engine may count on from any fluid model, checked
// on SPH, today's model; a second model meets the same tests.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/simulation.hpp"
#include "engine/sph_fluid.hpp"
#include "geometry/tissue.hpp"
#include "small_cell.hpp"

using namespace cellsim;
using cellsim::testing::small_cell_case;

namespace {

struct Built {
  explicit Built(const nlohmann::json& extra = nlohmann::json::object())
      : p(small_cell_case(extra)), tissue(build_tissue(p)), sim(p, tissue) {}
  Params p;
  Tissue tissue;
  Simulation sim;
  FluidContext context(const EquationOfState& eos) const {
    return {sim.surface(), sim.neighbours(), sim.cells(), eos, p.drying_Lp_m_per_s_Pa, 1};
  }
};

}  // namespace

// Its energy terms are the kinetic (its share), internal and coupling slots; it leaves every other
// term of the account to the engine (the wall's, the plates', the flows' integrals).
TEST(FluidModel, WritesOnlyItsOwnTermsOfTheStoredEnergy) {
  Built b;
  for (int n = 0; n < 20; ++n) b.sim.step();  // moving, so the kinetic energy is not zero
  constexpr double kUntouched = -12345.0;
  EnergyValues e;
  e.fill(kUntouched);
  b.sim.fluid().stored_energy(b.sim.state(), b.context(b.sim.eos()), e);
  for (const EnergyTerm& term : kEnergyTerms) {
    const bool its_own = term.id == kKinetic || term.id == kInternal || term.id == kCouplingPotential;
    if (its_own)
      EXPECT_NE(e[term.id], kUntouched) << term.label;
    else
      EXPECT_EQ(e[term.id], kUntouched) << term.label << " is the engine's";
  }
  const FluidParticles& f = b.sim.state().fluid;
  double kinetic_J = 0;
  for (Eigen::Index i = 0; i < f.size(); ++i) kinetic_J += 0.5 * f.m[i] * f.v.col(i).squaredNorm();
  EXPECT_GT(kinetic_J, 0.0);
  EXPECT_NEAR(e[kKinetic], kinetic_J, 1e-12 * kinetic_J);  // the fluid's share only, not the wall's
  EXPECT_GT(e[kCouplingPotential], 0.0);                     // LJ stores energy in its pairs
}

// The pressure coupling stores nothing of its own: its energy is the fluid's internal energy.
TEST(FluidModel, ThePressureCouplingStoresNoPotentialOfItsOwn) {
  Built b(nlohmann::json{{"coupling", {{"model", "pressure"}}}});
  EnergyValues e{};
  b.sim.fluid().stored_energy(b.sim.state(), b.context(b.sim.eos()), e);
  EXPECT_EQ(e[kCouplingPotential], 0.0);
}

// The wall-fluid pairs reach as far as the coupling does: the kernel's support 2h for the pressure
// coupling, LJ's r_c = max(r0, (r_c/h) h) for Lennard-Jones (model.md §3).
TEST(FluidModel, TheWallPairsReachAsFarAsItsCoupling) {
  const Built lj, pressure(nlohmann::json{{"coupling", {{"model", "pressure"}}}});
  SphFluid lj_fluid(lj.p, lj.tissue.cells, PropertyFactors{});
  SphFluid pressure_fluid(pressure.p, pressure.tissue.cells, PropertyFactors{});
  const double h = 2e-6;
  EXPECT_EQ(pressure_fluid.follow_smoothing_length(h), 2.0 * h);
  EXPECT_EQ(lj_fluid.follow_smoothing_length(h), std::max(*lj.p.r0_m, lj.p.attraction_cutoff_over_h * h));
  EXPECT_EQ(lj_fluid.follow_smoothing_length(1e-12), *lj.p.r0_m);  // never inside r0
}

// Its time-step limit is its own (the wall springs' is the engine's): within it at rest, exceeded when
// the same state's sound speed is raised a hundredfold (K x 10^4), and the message names the limit.
TEST(FluidModel, SaysWhichOfItsLimitsTheTimeStepExceeds) {
  Built b;
  EXPECT_EQ(dynamic_cast<const SphFluid&>(b.sim.fluid()).time_step_violation(b.sim.state(), b.context(b.sim.eos())), "");
  EquationOfState stiff = b.sim.eos();
  stiff.bulk_modulus_Pa *= 1e4;
  const std::string violation = dynamic_cast<const SphFluid&>(b.sim.fluid()).time_step_violation(b.sim.state(), b.context(stiff));
  EXPECT_NE(violation.find("sound-speed CFL limit"), std::string::npos) << violation;
  EXPECT_NE(violation.find("time.dt_ns"), std::string::npos) << violation;
}

// d(stored energy)/d(P_T) at fixed particles is sum m (1/rho0 - 1/rho): checked against a central
// difference of the internal energy in P_T.
TEST(FluidModel, TheTurgorDerivativeOfItsEnergyMatchesADifference) {
  Built b;
  for (int n = 0; n < 20; ++n) b.sim.step();  // densities away from rho0
  const EquationOfState eos = b.sim.eos();
  const auto internal_at = [&](double turgor_Pa) {
    EquationOfState at = eos;
    at.turgor_Pa = turgor_Pa;
    EnergyValues e{};
    b.sim.fluid().stored_energy(b.sim.state(), b.context(at), e);
    return e[kInternal];
  };
  const double dP = 1e3;
  const double difference = (internal_at(eos.turgor_Pa + dP) - internal_at(eos.turgor_Pa - dP)) / (2 * dP);
  const double derivative = b.sim.fluid().stored_energy_per_turgor_m3(b.sim.state(), eos);
  ASSERT_NE(derivative, 0.0);
  EXPECT_NEAR(difference / derivative, 1.0, 1e-6);
}

// The per-cell mean pressure is the mean over each cell's own particles.
TEST(FluidModel, ItsCellPressuresAreEachCellsOwnMean) {
  Built b(nlohmann::json{{"tissue", {{"cells_x", 2}}}});
  ASSERT_EQ(b.sim.cells().count(), 2);
  for (int n = 0; n < 5; ++n) b.sim.step();
  const Eigen::VectorXd& P = dynamic_cast<const SphFluid&>(b.sim.fluid()).pressure_Pa();
  const std::vector<double> mean = b.sim.cell_mean_fluid_pressure_Pa();
  ASSERT_EQ(mean.size(), 2u);
  for (int c = 0; c < 2; ++c)
    EXPECT_DOUBLE_EQ(mean[static_cast<std::size_t>(c)],
                     P.segment(b.sim.cells().fluid[c], b.sim.cells().fluid_count(c)).mean());
  EXPECT_NE(mean[0], mean[1]);
}
