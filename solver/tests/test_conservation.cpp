// Conservation laws of the assembled loops (model.md §9): fluid-fluid terms conserve momentum;
// viscosity alone dissipates kinetic energy; the whole cell conserves momentum without mass
// transfer and plates.
#include <gtest/gtest.h>

#include <random>

#include "engine/simulation.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"
#include "physics/fluid_pairs.hpp"
#include "fluid_box.hpp"
#include "small_cell.hpp"

using namespace cellsim;
using cellsim::testing::fluid_box;

namespace {

double kinetic_energy(const FluidParticles& f) {
  return 0.5 * (f.v.colwise().squaredNorm().transpose().array() * f.m.array()).sum();
}

}  // namespace

TEST(Conservation, FluidPairTermsConserveMomentum) {
  const double dx = 7.7e-6;
  FluidParticles f = fluid_box(8, dx, 3);
  NeighbourLists lists(0.1 * dx);
  const CubicSplineKernel kernel(1.3 * dx);
  lists.update(f.x, Eigen::Matrix3Xd(3, 0), kernel.support(), 0.0);
  FluidRates rates;
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, {2e5, 20e6, 1000, 7}, 0.1, 1, rates);
  const double scale = rates.force.colwise().norm().maxCoeff();
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(rates.force.rowwise().sum().norm(), 1e-12 * scale * f.size());
}

TEST(Conservation, ViscosityAloneDissipatesKineticEnergy) {
  const double dx = 7.7e-6, dt = 1e-9;
  FluidParticles f = fluid_box(6, dx, 5);
  f.rho.setConstant(1000.0);
  NeighbourLists lists(0.1 * dx);
  const CubicSplineKernel kernel(1.3 * dx);
  const EquationOfState no_pressure{0.0, 0.0, 1000.0, 7.0};  // K = 0, P_T = 0: viscous terms only
  FluidRates rates;
  double previous = kinetic_energy(f);
  const Eigen::Vector3d momentum0 = f.v * f.m;
  for (int step = 0; step < 200; ++step) {
    lists.update(f.x, Eigen::Matrix3Xd(3, 0), kernel.support(), 0.0);
    fluid_pair_terms(f, lists.fluid_fluid(), kernel, no_pressure, 0.1, 1, rates);
    for (Eigen::Index i = 0; i < f.size(); ++i) f.v.col(i) += dt / f.m[i] * rates.force.col(i);
    f.x += dt * f.v;
    const double now = kinetic_energy(f);
    ASSERT_LT(now, previous) << "step " << step;
    previous = now;
  }
  EXPECT_LT(previous, 0.9 * kinetic_energy(fluid_box(6, dx, 5)));
  EXPECT_LT((f.v * f.m - momentum0).norm(), 1e-12 * momentum0.norm() + 1e-24);
}

TEST(Conservation, WholeCellConservesMomentumWithoutMassTransfer) {
  Params p = cellsim::testing::small_cell_case(
      {{"drying", {{"Lp_m_per_s_Pa", 0}, {"pressure_closure_time_us", 0}, {"dryness", 0.5}}}});
  const Tissue cell = build_tissue(p);
  Simulation sim(p, cell);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> speed(-0.3, 0.3);
  State& s = sim.mutable_state();
  for (Eigen::Index i = 0; i < s.fluid.size(); ++i) s.fluid.v.col(i) << speed(rng), speed(rng), speed(rng);
  for (Eigen::Index k = 0; k < s.wall.size(); ++k) s.wall.v.col(k) << speed(rng), speed(rng), speed(rng);
  const auto momentum = [&] { return Eigen::Vector3d(s.fluid.v * s.fluid.m + s.wall.v.rowwise().sum() * s.wall.mass_kg); };
  const Eigen::Vector3d p0 = momentum();
  const double scale = (s.fluid.v.colwise().norm().transpose().array() * s.fluid.m.array()).sum();
  for (int n = 0; n < 300; ++n) sim.step();
  EXPECT_LT((momentum() - p0).norm(), 1e-10 * scale);
}
