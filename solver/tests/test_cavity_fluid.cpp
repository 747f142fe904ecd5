// The closed-cell fluid (engine/cavity_fluid.hpp, physics/cavity_pressure.hpp) and the quasi-static
// scheme (engine/quasi_static.hpp): Eq 11 over an increment, the pressure as the exact gradient of the
// stored energy, Young-Laplace at rest, the energy account dynamic and quasi-static, and the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "cli_helpers.hpp"
#include "core/errors.hpp"
#include "engine/cavity_fluid.hpp"
#include "engine/quasi_static.hpp"
#include "engine/settle.hpp"
#include "engine/simulation.hpp"
#include "engine/volumetric_modulus.hpp"
#include "geometry/tissue.hpp"
#include "io/state_io.hpp"
#include "physics/cavity_pressure.hpp"
#include "small_cell.hpp"

using namespace cellsim;
using cellsim::testing::small_cell_case;

namespace {

const nlohmann::json kCavity = {{"fluid", {{"model", "cavity"}}}};

nlohmann::json cavity_case(nlohmann::json extra = nlohmann::json::object()) {
  nlohmann::json doc = kCavity;
  doc.merge_patch(extra);
  return doc;
}

struct Built {
  explicit Built(const nlohmann::json& extra = kCavity) : p(small_cell_case(extra)), tissue(build_tissue(p)), sim(p, tissue) {}
  Params p;
  Tissue tissue;
  Simulation sim;
};

const EquationOfState kEos{200e3, 20e6, 1000, 7};

}  // namespace

// rho V = M_n - a rho (P(rho) - P_T) to round-off; a = 0 keeps the mass, a = infinity holds P = P_T.
TEST(CavityPressure, TheIncrementsDensityMeetsEq11BackwardEuler) {
  const double V = 1.7e-12;
  for (double mass_over_rho0V : {0.97, 1.0, 1.01, 1.3})
    for (double a : {0.0, 1e-26, 1e-19, 1e-17, 1e-14}) {
      const double M = mass_over_rho0V * 1000 * V;
      const double rho = implicit_cavity_density(M, V, a, kEos);
      const double excess = kEos.pressure(rho) - kEos.turgor_Pa;
      const double g = rho * V - M + a * rho * excess;
      const double scale = rho * V + a * rho * (std::abs(excess) + 7 * kEos.bulk_modulus_Pa);  // rho dg/drho
      EXPECT_NEAR(g, 0.0, 1e-13 * scale) << "M/(rho0 V) " << mass_over_rho0V << ", a " << a;
      if (a == 0) EXPECT_DOUBLE_EQ(rho, M / V);
    }
  EXPECT_EQ(implicit_cavity_density(1e-9, 1.7e-12, INFINITY, kEos), 1000.0);
  // A large a drains the cell toward P_T: the density lies between M/V and rho0.
  const double rho = implicit_cavity_density(1.02 * 1000 * 1.7e-12, 1.7e-12, 1e-14, kEos);
  EXPECT_GT(rho, 1000.0);
  EXPECT_LT(rho, 1020.0);
}

// dV/dx_k = vertex_normal / 6 is the derivative of the signed-tetrahedra volume (central differences on
// a cell with its particles moved off the sphere).
TEST(CavityPressure, TheVolumeGradientIsTheDerivativeOfTheEnclosedVolume) {
  Built b;
  Eigen::Matrix3Xd x = b.tissue.wall_x;
  for (Eigen::Index k = 0; k < x.cols(); ++k) x.col(k) *= 1.0 + 0.05 * std::sin(3.0 * k);
  const WallSurface at = wall_surface(x, b.tissue.mesh);
  const double h = 1e-9;
  for (Eigen::Index k : {0, 17, 80, 161})
    for (int d = 0; d < 3; ++d) {
      Eigen::Matrix3Xd plus = x, minus = x;
      plus(d, k) += h;
      minus(d, k) -= h;
      const double fd = (wall_surface(plus, b.tissue.mesh).volume_m3 - wall_surface(minus, b.tissue.mesh).volume_m3) / (2 * h);
      EXPECT_NEAR(volume_gradient(at.vertex_normal.col(k))[d], fd, 1e-7 * at.vertex_normal.col(k).norm())
          << "particle " << k << ", axis " << d;
    }
}

// No particles are built; each cell holds rho0 times its volume, at P = P_T0.
TEST(CavityFluid, BuildsNoParticlesAndFillsEachCellAtRho0) {
  Built b(cavity_case({{"tissue", {{"cells_x", 2}}}}));
  const State& s = b.sim.state();
  EXPECT_EQ(s.fluid.size(), 0);
  ASSERT_EQ(s.cavity_mass_kg.size(), 2u);
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(s.cavity_mass_kg[c], 1000 * b.sim.surface().cell_volume_m3[c], 1e-12 * s.cavity_mass_kg[c]);
    EXPECT_NEAR(b.sim.cell_mean_fluid_pressure_Pa()[c], b.p.turgor_Pa, 1e-6 * b.p.turgor_Pa);
  }
  const Record r = b.sim.record();
  EXPECT_DOUBLE_EQ(r.fluid_mass_ratio, 1.0);
  EXPECT_NEAR(r.fluid_volume_ratio, 1.0, 1e-14);
  EXPECT_EQ(r.kinetic_energy_fluid_J, 0.0);
}

// F_k = P dV/dx_k is minus the derivative of the fluid's stored energy M e(M/V) at fixed M.
TEST(CavityFluid, PushesOnTheWallAsMinusTheGradientOfItsStoredEnergy) {
  Built b;
  State& s = b.sim.mutable_state();
  s.cavity_mass_kg[0] *= 1.004;  // a pressure above the turgor: the wall is pushed out
  for (Eigen::Index k = 0; k < s.wall.size(); ++k) s.wall.x.col(k) *= 1.0 + 0.02 * std::cos(5.0 * k);
  b.sim.refresh_rates();
  CavityFluid cavity(b.p);
  const auto context = [&](const WallSurface& surface) {
    return FluidContext{surface, b.sim.neighbours(), b.sim.cells(), b.sim.eos(), 0.0, 1};
  };
  const auto internal_J = [&](const Eigen::Matrix3Xd& x) {
    const WallSurface surface = wall_surface(x, b.tissue.mesh);
    EnergyValues e{};
    cavity.stored_energy(s, context(surface), e);
    return e[kInternal];
  };
  EnergyValues power{};
  Eigen::Matrix3Xd on_wall, backstop;
  cavity.compute_forces(s, context(b.sim.surface()), false, power);
  cavity.couple_to_wall(s, context(b.sim.surface()), false, on_wall, backstop, power);
  EXPECT_GT(cavity.cell_mean_pressure_Pa(b.sim.cells())[0], b.p.turgor_Pa);
  EXPECT_EQ(backstop.norm(), 0.0);
  const double h = 1e-10;
  for (Eigen::Index k : {3, 60, 120})
    for (int d = 0; d < 3; ++d) {
      Eigen::Matrix3Xd plus = s.wall.x, minus = s.wall.x;
      plus(d, k) += h;
      minus(d, k) -= h;
      const double force = -(internal_J(plus) - internal_J(minus)) / (2 * h);
      EXPECT_NEAR(on_wall(d, k), force, 1e-5 * on_wall.col(k).norm()) << "particle " << k << ", axis " << d;
    }
}

// At rest after the settle, the wall carries the pressure: the virial of a closed network in equilibrium,
// sum of tension x length = 3 P V (bending's share aside), so the wall tension sum / (2 A) is P R / 2 for
// a sphere (Young-Laplace); and the cell sits at P_T0 with mass rho0 V.
TEST(CavityFluid, AtRestTheWallCarriesThePressureByYoungLaplace) {
  Built b(cavity_case({{"time", {{"equilibrium_tolerance", 1e-6}}}}));
  const SettleReport settled = settle(b.sim, 200000, 0);
  ASSERT_TRUE(settled.converged) << settled.residual;
  const Record r = b.sim.record();
  const double P = r.mean_pressure_Pa, V = r.volume_m3, A = r.area_m2;
  EXPECT_NEAR(P, b.p.turgor_Pa, 1e-9 * b.p.turgor_Pa);
  EXPECT_NEAR(r.wall_tension_N_m, 3 * P * V / (2 * A), 2e-3 * r.wall_tension_N_m);
  const double R = 0.5 * r.equivalent_diameter_m;
  EXPECT_NEAR(P, 2 * r.wall_tension_N_m / R, 1e-2 * P);
  // The outward push along the unit vertex normals / area: |sum of a vertex's triangle normals| / 6 falls
  // short of a third of their areas where the mesh is curved (1.6 % at 162 particles).
  EXPECT_NEAR(r.wall_pressure_Pa, P, 3e-2 * P);
  EXPECT_GT(settled.volume_ratio, 1.0);           // the turgor inflated it
}

// Dynamic (the wall's masses, the plate at its speed): the plate's work is the stored energy's change
// and the losses, to 1e-4 of it.
TEST(CavityFluid, ADynamicCompressionClosesTheEnergyAccount) {
  Built b;
  settle(b.sim, 100000, 0);
  for (int n = 0; n < 2000; ++n) b.sim.step();
  b.sim.start_compression();
  while (b.sim.nominal_strain() < 0.1) b.sim.step();
  const Record r = b.sim.record();
  ASSERT_GT(r.energy[kPlateWork], 0.0);
  EXPECT_LT(std::abs(r.energy_residual_J), 1e-4 * r.energy[kPlateWork]) << r.energy_residual_J;
  EXPECT_GT(r.mean_pressure_Pa, b.p.turgor_Pa);  // sealed (L_p 1e-12): squeezed, it pressurises
  EXPECT_NEAR(r.load_fluid_N, r.mean_pressure_Pa * r.contact_area_top_m2, 0.2 * r.load_fluid_N);
}

// Quasi-static drying (a sequence of equilibria while the ramp moves P_T and L_ref, Eq 11 integrated over
// each step): every step ends at rest; the dried cell is drained to P_T(X) at rho0, so M/M0 = V/V0; and the
// account's residual is a small part of the energy the drive put in.
TEST(QuasiStatic, ADryingIsASequenceOfEquilibriaThatEndsDrainedAtTheTurgorOfItsDryness) {
  Built b(cavity_case({{"time", {{"scheme", "quasi_static"}, {"dt_ns", 500}}}, {"drying", {{"dryness", 0.5}}}}));
  settle(b.sim, 100000, 0);
  QuasiStaticScheme scheme(b.sim);
  const double V0 = b.sim.surface().volume_m3;
  for (int n = 0; n < 60; ++n) {  // the 20 us ramp and 10 us beyond
    scheme.step();
    ASSERT_EQ(b.sim.state().wall.v.norm(), 0.0);
  }
  const Record r = b.sim.record();
  EXPECT_NEAR(r.mean_pressure_Pa, 0.5 * b.p.turgor_Pa, 1e-3 * b.p.turgor_Pa);
  EXPECT_NEAR(r.fluid_mass_ratio, r.volume_m3 / V0, 1e-3);
  EXPECT_LT(r.volume_m3 / V0, 0.8);  // the contraction springs shrank it
  const double drive_J = std::abs(r.energy[kDrive]);
  ASSERT_GT(drive_J, 0.0);
  EXPECT_LT(std::abs(r.energy_residual_J), 1e-3 * drive_J) << r.energy_residual_J << " of " << drive_J;
}

// Quasi-static compression (a sequence of equilibria while the plate moves): every step ends at rest
// within its test, the plates hold the cell with equal and opposite forces, the plate's work is the
// trapezoid of its force over its travel, and that work is the stored energy's change plus what the
// relaxations released (a non-negative share: a wall that folds gives energy back in snaps).
TEST(QuasiStatic, ACompressionIsASequenceOfEquilibriaThatThePlatesHoldAlike) {
  Built b(cavity_case({{"time", {{"scheme", "quasi_static"}, {"dt_ns", 200}}}}));
  settle(b.sim, 100000, 0);
  QuasiStaticScheme scheme(b.sim);
  scheme.step();
  scheme.start_compression();
  Record last = b.sim.record();
  const Record start = last;
  double curve_work_J = 0;
  while (last.nominal_strain < 0.1) {
    scheme.step();
    const Record r = b.sim.record();
    ASSERT_LE(r.relaxation_residual, b.p.equilibrium_tolerance);
    ASSERT_GE(r.relaxation_evaluations, 1.0);
    ASSERT_EQ(b.sim.state().wall.v.norm(), 0.0);
    curve_work_J += 0.5 * (last.plate_force_top_N + r.plate_force_top_N) * (last.plate_top_z_m - r.plate_top_z_m);
    last = r;
  }
  ASSERT_GT(last.plate_force_top_N, 0.0);
  // Equilibrium: the forces left on the particles sum to at most tolerance x P x the wall's area.
  const double imbalance_bound_N = b.p.equilibrium_tolerance * last.mean_pressure_Pa * last.area_m2;
  EXPECT_NEAR(last.plate_force_top_N, last.plate_force_bottom_N, imbalance_bound_N);
  const auto change = [&](EnergyTermId term) { return last.energy[term] - start.energy[term]; };
  const double work_J = change(kPlateWork);
  EXPECT_NEAR(work_J, curve_work_J, 1e-9 * curve_work_J);
  const double released_J = change(kRelaxationLoss);
  EXPECT_GE(released_J, -1e-6 * work_J);
  EXPECT_LT(released_J, 0.5 * work_J);
  EXPECT_NEAR(last.stored_energy_J - start.stored_energy_J, work_J - released_J + change(kMassTransfer), 1e-9 * work_J);
  EXPECT_LT(std::abs(last.energy_residual_J), 1e-9 * work_J);
}

// A wall that yields, compressed quasi-statically: the history kept is that of the accepted points (the
// probes and rejected trials put theirs back), so one more evaluation at the equilibrium moves no plastic
// slider; the flow dissipated, and the account closes.
TEST(QuasiStatic, AYieldingWallKeepsOnlyTheHistoryOfItsAcceptedPoints) {
  Built b(cavity_case({{"time", {{"scheme", "quasi_static"}, {"dt_ns", 200}}}, {"wall", {{"yield_stress_MPa", 1.5}}}}));
  settle(b.sim, 100000, 0);
  QuasiStaticScheme scheme(b.sim);
  scheme.step();
  scheme.start_compression();
  while (b.sim.nominal_strain() < 0.08) scheme.step();
  const std::vector<double> plastic = b.sim.state().bond_plastic_elongation_m;
  const double plastic_loss_J = b.sim.state().energy.integral[kPlasticLoss];
  ASSERT_GT(*std::max_element(plastic.begin(), plastic.end()), 0.0) << "the wall did not yield: no test";
  EXPECT_GT(plastic_loss_J, 0.0);
  b.sim.refresh_rates();
  EXPECT_EQ(b.sim.state().bond_plastic_elongation_m, plastic);
  EXPECT_EQ(b.sim.state().energy.integral[kPlasticLoss], plastic_loss_J);
  const Record r = b.sim.record();
  EXPECT_LT(std::abs(r.energy_residual_J), 1e-9 * r.energy[kPlateWork]);
}

// Adaptive increments (time.min_increment_ns below time.dt_ns), cutting at every loss above 1e-9 of the loads'
// work: each step still ends on the plate position it asks for (the records stay on the asked strains, to
// round-off of the increments' sum), the account closes as the fixed steps' does, and the cut increments cost
// more relaxations than the fixed ones.
TEST(QuasiStatic, AdaptiveIncrementsKeepTheStepsPlatesAndTheAccount) {
  const auto compressed = [](double least_fraction) {
    auto b = std::make_unique<Built>(cavity_case({{"time", {{"scheme", "quasi_static"}, {"dt_ns", 400},
                                                            {"min_increment_ns", 400 * least_fraction},
                                                            {"snap_loss_share", 1e-9}}}}));
    settle(b->sim, 100000, 0);
    QuasiStaticScheme scheme(b->sim);
    scheme.step();
    scheme.start_compression();
    std::vector<double> top_z_m;
    double evaluations = 0;
    for (int n = 0; n < 12; ++n) {
      scheme.step();
      top_z_m.push_back(b->sim.state().plates.top_z_m);
      evaluations += b->sim.state().relaxation_evaluations;
    }
    const Record r = b->sim.record();
    EXPECT_GT(r.energy[kPlateWork], 0.0);
    EXPECT_LT(std::abs(r.energy_residual_J), 1e-9 * r.energy[kPlateWork]) << "least fraction " << least_fraction;
    return std::make_pair(top_z_m, evaluations);
  };
  const auto fixed = compressed(1.0), adaptive = compressed(1.0 / 16);
  ASSERT_EQ(fixed.first.size(), adaptive.first.size());
  for (std::size_t n = 0; n < fixed.first.size(); ++n)
    EXPECT_NEAR(adaptive.first[n], fixed.first[n], 1e-12 * std::abs(fixed.first[n])) << "step " << n;
  EXPECT_GT(adaptive.second, fixed.second);
}

// Where the loads do no work (a drying cell past its ramp, whose water still drains) a relaxation releases
// a little, which no share of the loads' zero work bounds: below the energy a relaxation resolves (its
// tolerance's force over a bond), it is no snap. So with a snap share too large to cut in the ramp, the
// adaptive drying is the fixed one, step for step (before that floor, every step past the ramp was cut to
// its least increment).
TEST(QuasiStatic, AdaptiveIncrementsDoNotCutAStepWhereTheLoadsDoNoWork) {
  const auto dried = [](double least_fraction) {
    Built b(cavity_case({{"time", {{"scheme", "quasi_static"}, {"dt_ns", 500}, {"snap_loss_share", 1e3},
                                   {"increment_move_over_spacing", 0},
                                   {"min_increment_ns", 500 * least_fraction}}},
                         {"drying", {{"dryness", 0.5}}}}));
    settle(b.sim, 100000, 0);
    QuasiStaticScheme scheme(b.sim);
    std::vector<double> evaluations;
    for (int n = 0; n < 60; ++n) {  // the 20 us ramp and 10 us beyond
      scheme.step();
      evaluations.push_back(b.sim.state().relaxation_evaluations);
    }
    return evaluations;
  };
  const std::vector<double> fixed = dried(1.0), adaptive = dried(1.0 / 64);
  EXPECT_EQ(adaptive, fixed);
}

// time.increment_move_over_spacing: an increment whose relaxation moves a wall particle farther than that
// share of a bond is cut (the snap share set too large to cut), so a limit well below the plate's step (each step moves the plate 0.4 um,
// about 7 % of the small cell's 5.6 um bond) cuts every step into several increments: more relaxations than without
// the limit, the plates still where the steps ask, and the account closed.
TEST(QuasiStatic, AnIncrementThatMovesTheWallFartherThanItsLimitIsCut) {
  const auto compressed = [](double move_over_spacing) {
    Built b(cavity_case({{"time", {{"scheme", "quasi_static"}, {"dt_ns", 400}, {"min_increment_ns", 400.0 / 64},
                                   {"snap_loss_share", 1e3}, {"increment_move_over_spacing", move_over_spacing}}}}));
    settle(b.sim, 100000, 0);
    QuasiStaticScheme scheme(b.sim);
    scheme.start_compression();
    std::vector<double> top_z_m;
    double evaluations = 0;
    for (int n = 0; n < 10; ++n) {
      scheme.step();
      top_z_m.push_back(b.sim.state().plates.top_z_m);
      evaluations += b.sim.state().relaxation_evaluations;
    }
    const Record r = b.sim.record();
    EXPECT_GT(r.energy[kPlateWork], 0.0);
    EXPECT_LT(std::abs(r.energy_residual_J), 1e-9 * r.energy[kPlateWork]) << "limit " << move_over_spacing;
    return std::make_pair(top_z_m, evaluations);
  };
  const auto unlimited = compressed(0), limited = compressed(0.005);
  for (std::size_t n = 0; n < unlimited.first.size(); ++n)
    EXPECT_NEAR(limited.first[n], unlimited.first[n], 1e-12 * std::abs(unlimited.first[n])) << "step " << n;
  EXPECT_GT(limited.second, 1.5 * unlimited.second);
}

// time.predictor = secant: each relaxation starts from the last equilibrium moved by the last increment's
// motion where that starts nearer equilibrium. On the small cell's smooth path (20 fixed steps of 0.2 um;
// at the 21st the plain start dips onto a dimpled equilibrium for one step, where the secant keeps on) it
// reaches the same equilibria, each within its tolerance (the plate forces within the two relaxations'
// residual budgets, 2 x tolerance x max(P_T0, |P|) x the wall's area; the relaxations' loss, the
// trapezoid's error here, the same), in fewer force evaluations; the account closes.
TEST(QuasiStatic, TheSecantPredictorReachesTheSameEquilibriaInFewerEvaluations) {
  struct Path {
    std::vector<double> force_N;
    double evaluations = 0, load_N = 0;  // load: the largest max(P_T0, |P|) x the wall's area
    double tolerance = 0;
    double released_J = 0, work_J = 0;  // the relaxations' loss and the plate's work in compression
  };
  const auto compressed = [](const char* predictor) {
    Built b(cavity_case({{"time", {{"scheme", "quasi_static"}, {"dt_ns", 200}, {"predictor", predictor}}}}));
    settle(b.sim, 100000, 0);
    QuasiStaticScheme scheme(b.sim);
    scheme.start_compression();
    const Record start = b.sim.record();
    Path path;
    path.tolerance = b.p.equilibrium_tolerance;
    for (int n = 0; n < 20; ++n) {
      scheme.step();
      const Record r = b.sim.record();
      path.force_N.push_back(r.plate_force_top_N);
      path.evaluations += r.relaxation_evaluations;
      path.load_N = std::max(path.load_N, std::max(b.p.turgor_Pa, std::abs(r.mean_pressure_Pa)) * r.area_m2);
    }
    const Record r = b.sim.record();
    EXPECT_LT(std::abs(r.energy_residual_J), 1e-9 * r.energy[kPlateWork]) << predictor;
    path.released_J = r.energy[kRelaxationLoss] - start.energy[kRelaxationLoss];
    path.work_J = r.energy[kPlateWork] - start.energy[kPlateWork];
    return path;
  };
  const Path plain = compressed("none"), secant = compressed("secant");
  const double bound_N = 2 * plain.tolerance * plain.load_N;
  ASSERT_EQ(secant.force_N.size(), plain.force_N.size());
  for (std::size_t n = 0; n < plain.force_N.size(); ++n)
    EXPECT_NEAR(secant.force_N[n], plain.force_N[n], bound_N) << "step " << n;
  EXPECT_GT(plain.force_N.back(), 10 * bound_N);  // the bound is tight against the forces compared
  EXPECT_NEAR(secant.released_J, plain.released_J, 1e-4 * plain.work_J);  // the same equilibria, the same account
  EXPECT_LT(secant.evaluations, 0.9 * plain.evaluations);
  std::printf("evaluations: plain %.0f, secant %.0f; plate force %.3g N, bound %.3g N\n", plain.evaluations,
              secant.evaluations, plain.force_N.back(), bound_N);
}

// A step whose relaxation fails at its least increment stops (exit 3 through NumericalFailure), naming its
// strain and the key that bounds the cuts.
TEST(QuasiStatic, AStepThatCannotBeCutFurtherStopsNamingItsStrainAndTheKey) {
  Built b(cavity_case({{"time", {{"scheme", "quasi_static"}, {"dt_ns", 400}, {"min_increment_ns", 100},
                                 {"relaxation_max_iterations", 2}}}}));
  settle(b.sim, 100000, 0);
  QuasiStaticScheme scheme(b.sim);
  try {
    scheme.start_compression();
    for (int n = 0; n < 20; ++n) scheme.step();
    FAIL() << "no step failed";
  } catch (const NumericalFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("strain"), std::string::npos) << what;
    EXPECT_NE(what.find("time.min_increment_ns = 100"), std::string::npos) << what;
    EXPECT_NE(what.find("time.relaxation_max_iterations = 2"), std::string::npos) << what;
  }
}

// The volumetric modulus V dP/dV at rest is the wall's: the water's K decides how much of an injected mass
// compresses it, not the pressure the wall holds at a volume. So a tenfold K leaves it within 1 %; and the
// state is put back as it was.
TEST(CavityFluid, TheVolumetricModulusIsTheWallsWhateverK) {
  const auto modulus_with_K = [](double K_MPa) {
    Built b(cavity_case({{"fluid", {{"bulk_modulus_MPa", K_MPa}}}, {"time", {{"scheme", "quasi_static"}}}}));
    settle(b.sim, 100000, 0);
    const State before = b.sim.state();
    const double eps_Pa = volumetric_modulus_Pa(b.sim);
    EXPECT_EQ(b.sim.state().wall.x, before.wall.x);
    EXPECT_EQ(b.sim.state().cavity_mass_kg, before.cavity_mass_kg);
    return eps_Pa;
  };
  const double soft = modulus_with_K(20), stiff = modulus_with_K(200);
  EXPECT_GT(soft, 0.0);
  EXPECT_NEAR(stiff / soft, 1.0, 1e-2) << soft << " " << stiff;
  Built sph(nlohmann::json{{"fluid", {{"model", "sph"}}}});
  EXPECT_TRUE(std::isnan(volumetric_modulus_Pa(sph.sim)));
}

// The example of a closed cell (solver/examples/apple-closed-cell.json) validates without a warning and,
// on a small wall, runs to its end strain with every step at equilibrium.
TEST(QuasiStatic, TheClosedCellExampleRuns) {
  cellsim::testing::ScratchDir dir("closed cell example");
  const std::string example = std::string(CELLSIM_SOURCE_DIR) + "/solver/examples/apple-closed-cell.json";
  const auto validated = cellsim::testing::run_cli({"validate", example}, dir);
  EXPECT_EQ(validated.exit_code, 0) << validated.err;
  EXPECT_EQ(validated.err.find("WARNING"), std::string::npos) << validated.err;
  const auto ran = cellsim::testing::run_cli({"run", example, "-o", dir.file("out.h5"), "--quiet", "--set", "cell.n_wall=162",
                                              "--set", "cell.diameter_um=40", "--set", "compression.end_strain=0.05"},
                                             dir);
  ASSERT_EQ(ran.exit_code, 0) << ran.err;
  EXPECT_TRUE(std::filesystem::exists(dir.file("out.h5")));
}

// The contracts of test_fluid_model.cpp, for the closed cell: it writes only its own terms of the stored
// energy (no particles: no kinetic share, no coupling potential), its turgor derivative matches a
// difference, and it names the limit a time step exceeds.
TEST(CavityFluid, MeetsTheFluidModelsContracts) {
  Built b;
  for (int n = 0; n < 50; ++n) b.sim.step();  // Eq 11 moves the mass: the density leaves rho0
  const FluidContext context = b.sim.fluid_context();
  constexpr double kUntouched = -12345.0;
  EnergyValues e;
  e.fill(kUntouched);
  b.sim.fluid().stored_energy(b.sim.state(), context, e);
  for (const EnergyTerm& term : kEnergyTerms) {
    const bool its_own = term.id == kKinetic || term.id == kInternal || term.id == kCouplingPotential;
    EXPECT_EQ(e[term.id] == kUntouched, !its_own) << term.label;
  }
  EXPECT_EQ(e[kKinetic], 0.0);
  EXPECT_EQ(e[kCouplingPotential], 0.0);
  const auto internal_at = [&](double turgor_Pa) {
    FluidContext at = context;
    at.eos.turgor_Pa = turgor_Pa;
    EnergyValues values{};
    b.sim.fluid().stored_energy(b.sim.state(), at, values);
    return values[kInternal];
  };
  const double dP = 1e3, P_T = context.eos.turgor_Pa;
  const double derivative = b.sim.fluid().stored_energy_per_turgor_m3(b.sim.state(), context.eos);
  ASSERT_NE(derivative, 0.0);
  EXPECT_NEAR((internal_at(P_T + dP) - internal_at(P_T - dP)) / (2 * dP) / derivative, 1.0, 1e-6);
  EXPECT_EQ(dynamic_cast<const CavityFluid&>(b.sim.fluid()).time_step_violation(b.sim.state(), context), "");

  Built stiff(cavity_case({{"fluid", {{"bulk_modulus_MPa", 1e5}}}, {"drying", {{"Lp_m_per_s_Pa", 1e-3}}}}));
  const std::string violation = dynamic_cast<const CavityFluid&>(stiff.sim.fluid()).time_step_violation(stiff.sim.state(), stiff.sim.fluid_context());
  EXPECT_NE(violation.find("time.dt_ns"), std::string::npos) << violation;
  EXPECT_NE(violation.find("closed cell"), std::string::npos) << violation;
}

// A saved closed cell continues: its masses are in the state; one of the wrong length is refused.
TEST(CavityFluid, ItsMassesAreStateThatARestoreChecks) {
  Built b;
  for (int n = 0; n < 20; ++n) b.sim.step();
  State saved = b.sim.state();
  Built again;
  again.sim.restore(saved);
  EXPECT_EQ(again.sim.state().cavity_mass_kg, saved.cavity_mass_kg);
  saved.cavity_mass_kg.push_back(1e-12);
  EXPECT_THROW(check_restorable(saved, again.sim.state(), again.sim.mesh().bonds.size()), InputError);
  saved.cavity_mass_kg.pop_back();
  saved.cavity_mass_kg[0] = -1;
  EXPECT_THROW(check_restorable(saved, again.sim.state(), again.sim.mesh().bonds.size()), InputError);
}

// A tissue's cells press on each other through their contacts and middle lamella, which the Newton steps'
// preconditioner holds (engine/newton_preconditioner.hpp): four closed cells side by side between the
// plates, compressed quasi-statically to strain 0.08, reach every equilibrium in at most 200 force
// evaluations and all 59 in under 2000 (779 and at most 59 a step with them; without them 10 877 and
// up to 1826 a step, the conjugate gradients meeting each stiff contact anew), and the energy account
// closes.
TEST(QuasiStatic, CellsPressingOnEachOtherRelaxInFewEvaluations) {
  Built b(cavity_case({{"time", {{"scheme", "quasi_static"}, {"dt_ns", 100}}}, {"tissue", {{"cells_x", 2}, {"cells_y", 2}}}}));
  settle(b.sim, 100000, 0);
  QuasiStaticScheme scheme(b.sim);
  scheme.step();
  scheme.start_compression();
  double most_evaluations = 0, evaluations = 0;
  while (b.sim.nominal_strain() < 0.08) {
    scheme.step();
    const Record r = b.sim.record();
    ASSERT_LE(r.relaxation_residual, b.p.equilibrium_tolerance);
    most_evaluations = std::max(most_evaluations, r.relaxation_evaluations);
    evaluations += r.relaxation_evaluations;
  }
  const Record r = b.sim.record();
  ASSERT_GT(r.plate_force_top_N, 0.0);
  EXPECT_LT(most_evaluations, 200);
  EXPECT_LT(evaluations, 2000);
  EXPECT_LT(std::abs(r.energy_residual_J), 1e-9 * r.energy[kPlateWork]);
}
