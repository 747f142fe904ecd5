// The elastic-plastic wall bond (wall_plasticity.hpp, docs/model.md §3b): elastic below yield, flow on
// the flow stress above it, elastic unloading to a permanent set equal to the plastic strain, and a
// cycle's dissipation equal to its loop's area; the same law in the cell's bond loop keeps the energy
// account.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/simulation.hpp"
#include "geometry/tissue.hpp"
#include "physics/wall_bonds.hpp"
#include "physics/wall_plasticity.hpp"
#include "small_cell.hpp"

using namespace cellsim;

namespace {

// The default wall's bond (G 18 MPa, t0 6 um, k_wc 1e4 N/m, fresh: L_ref = l0), 5 um long, yielding at
// 3 MPa with a hardening of 200 MPa.
constexpr double kL0 = 5e-6, kThickness = 6e-6;
const wall::BondSprings kSprings{18e6 * kThickness, 1e4, kL0, kL0};
const wall::PlasticLaw kLaw{3e6, 200e6};

// A bond driven through lengths l: its tension after each return map, its slider, the energy the return
// maps took out of the springs, and the work of the tension over the path (trapezoids).
struct Path {
  double slider = 0, dissipated_J = 0, work_J = 0, last_l = kL0, last_tension = 0;
  void go_to(double l) {
    const double flowed = wall::return_map(kLaw, kSprings, kThickness, slider, l);
    dissipated_J += kSprings.energy(l - slider) - kSprings.energy(l - flowed);
    slider = flowed;
    const double t = kSprings.tension(l - slider);
    work_J += 0.5 * (t + last_tension) * (l - last_l);
    last_l = l;
    last_tension = t;
  }
  void sweep(double to, int steps) {
    const double from = last_l;
    for (int n = 1; n <= steps; ++n) go_to(from + (to - from) * n / steps);
  }
};

double yield_length() {  // where the elastic bond's tension reaches the yield tension (bisection)
  double lo = kL0, hi = 1.1 * kL0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (kSprings.tension(mid) < wall::flow_tension(kLaw, kThickness, kL0, 0.0) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

TEST(WallPlasticity, ABondIsElasticBelowYield) {
  const double l_y = yield_length();
  EXPECT_GT(l_y, kL0 * 1.0005);  // 3 MPa over t0 l0 / sqrt 3 is 52 uN, ~0.1 % of stretch at 1e4 N/m
  EXPECT_LT(l_y, kL0 * 1.005);
  Path path;
  path.sweep(0.999 * l_y, 100);
  EXPECT_EQ(path.slider, 0.0);
  EXPECT_EQ(path.dissipated_J, 0.0);
  path.sweep(kL0, 100);  // and back: the same curve, no set
  EXPECT_NEAR(path.work_J, 0.0, 1e-12 * kSprings.energy(l_y));
}

TEST(WallPlasticity, ABondFlowsOnTheFlowStressAndHardens) {
  const double l_y = yield_length();
  Path path;
  path.sweep(l_y * 1.01, 2000);
  const double plastic_strain = path.slider / kL0;
  EXPECT_GT(plastic_strain, 0.009);  // nearly all of the 1 % past yield: the hardening is 2 % of the springs'
  EXPECT_NEAR(path.last_tension, wall::flow_tension(kLaw, kThickness, kL0, path.slider), 1e-10 * path.last_tension);
  // The hardening: the flow tension is sigma_y + H eps_p over the section t0 l0 / sqrt 3.
  EXPECT_NEAR(path.last_tension, (3e6 + 200e6 * plastic_strain) * kThickness * kL0 / std::sqrt(3.0),
              1e-10 * path.last_tension);
  EXPECT_GT(path.last_tension, wall::flow_tension(kLaw, kThickness, kL0, 0.0) * 1.0005);
}

TEST(WallPlasticity, UnloadingIsElasticToAPermanentSetEqualToThePlasticStrain) {
  const double l_y = yield_length();
  Path path;
  path.sweep(l_y * 1.02, 2000);
  const double slider_at_peak = path.slider;
  path.sweep(kL0, 2000);  // back to the fabricated length: the bond is now in compression
  EXPECT_EQ(path.slider, slider_at_peak);  // unloading and compression do not flow (tension only)
  EXPECT_LT(path.last_tension, 0.0);
  // Unloaded (zero tension) the bond is l0 + delta_p long: its permanent set is the plastic strain.
  EXPECT_EQ(kSprings.tension(kL0 + slider_at_peak - slider_at_peak), 0.0);
  EXPECT_GT(slider_at_peak / kL0, 0.01);
}

TEST(WallPlasticity, ACycleDissipatesTheAreaOfItsLoop) {
  const double l_y = yield_length();
  Path path;  // from rest (zero tension) out past yield and back to zero tension: a closed loop in tension
  path.sweep(l_y * 1.03, 40000);
  path.sweep(kL0 + path.slider, 40000);
  EXPECT_NEAR(path.last_tension, 0.0, 1e-12);
  EXPECT_GT(path.dissipated_J, 0.0);
  // Both ends store nothing, so the loop's area (the work of the tension) is what the flow dissipated.
  EXPECT_NEAR(path.work_J, path.dissipated_J, 1e-3 * path.dissipated_J);
  // And that is the slider's work, the flow tension over the plastic elongation: (T_y + T_now) / 2 x delta_p.
  const double section = kThickness * kL0 / std::sqrt(3.0);
  EXPECT_NEAR(path.dissipated_J, (3e6 + 0.5 * 200e6 * path.slider / kL0) * section * path.slider,
              1e-3 * path.dissipated_J);
  // A second cycle to the same length is elastic: the loop has closed on the new rest length.
  const double dissipated = path.dissipated_J;
  path.sweep(l_y * 1.03, 40000);
  path.sweep(kL0 + path.slider, 40000);
  EXPECT_NEAR(path.dissipated_J, dissipated, 1e-9 * dissipated);
}

TEST(WallPlasticity, TheCellsBondLoopYieldsAndKeepsTheEnergyAccount) {
  // The small cell with a wall that yields at a tenth of its turgor stress: the settle and the first
  // steps stretch it past yield. The flow's loss is in the account and the sliders lengthen.
  Params p = cellsim::testing::small_cell_case({{"wall", {{"yield_stress_MPa", 0.05}, {"hardening_MPa", 10}}},
                                       {"drying", {{"dryness", 1.0}}}});
  const Tissue tissue = build_tissue(p);
  Simulation sim(p, tissue);
  for (int n = 0; n < 4000; ++n) sim.step();
  const State& s = sim.state();
  double largest_set = 0;
  for (std::size_t b = 0; b < s.bond_plastic_elongation_m.size(); ++b) {
    EXPECT_GE(s.bond_plastic_elongation_m[b], 0.0) << "bond " << b;
    largest_set = std::max(largest_set, s.bond_plastic_elongation_m[b] / sim.mesh().rest_length_m[b]);
  }
  EXPECT_GT(largest_set, 1e-4);
  EXPECT_GT(s.energy.integral[kPlasticLoss], 0.0);
  const Record r = sim.record();
  EXPECT_NEAR(r.wall_plastic_strain_max, largest_set, 1e-15);
  EXPECT_LT(std::abs(r.energy_residual_J), 0.02 * s.energy.integral[kPlasticLoss] + 1e-3 * r.stored_energy_J);
}
