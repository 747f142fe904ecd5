// The force field (engine/force_field.hpp, engine/force_terms.hpp): its three loops over one list, and each
// term's stiffness against its own forces.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "engine/force_field.hpp"
#include "engine/quasi_static.hpp"
#include "engine/simulation.hpp"
#include "geometry/surface.hpp"
#include "geometry/tissue.hpp"
#include "small_cell.hpp"

using namespace cellsim;
using cellsim::testing::small_cell_case;

namespace {

// A term of the test's own: each wall particle pulled to the origin by a spring of k_N_m, its energy in
// the plate springs' row, and a power in the plate work's.
class SpringToOrigin final : public ForceTerm {
 public:
  explicit SpringToOrigin(double k_N_m) : k_N_m_(k_N_m) {}
  void add_forces(State& s, const ForceContext&, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W) override {
    wall_force -= k_N_m_ * s.wall.x;
    power_W[kPlateWork] = 1.5;
  }
  void add_energy(const State& s, const ForceContext&, EnergyValues& e) const override {
    e[kPlateSprings] = 0.5 * k_N_m_ * s.wall.x.squaredNorm();
  }
  bool add_stiffness(const State& s, const ForceContext&, BlockStiffness& K) const override {
    for (int k = 0; k < static_cast<int>(s.wall.x.cols()); ++k) K.add(k, k, k_N_m_ * Eigen::Matrix3d::Identity());
    return true;
  }
  Phase phase() const override { return Phase::Plates; }

 private:
  double k_N_m_;
};

// The small closed cell, its wall rough and stretched by 10 % (every bond in tension, so the springs'
// stiffness has no left-out part), mid-drying at X/X0 = 0.5, sliders of 0.02 l0 on a third of the bonds,
// and squeezed: both plates 2 um into their range of the wall's extremes.
struct SqueezedCell {
  SqueezedCell()
      : p(small_cell_case({{"fluid", {{"model", "cavity"}}}, {"drying", {{"dryness", 0.5}}}})),
        tissue(build_tissue(p)),
        sim(p, tissue) {
    State& s = sim.mutable_state();
    for (Eigen::Index k = 0; k < s.wall.x.cols(); ++k) s.wall.x.col(k) *= 1.10 * (1.0 + 0.05 * std::sin(3.0 * k));
    for (std::size_t b = 0; b < s.bond_plastic_elongation_m.size(); b += 3)
      s.bond_plastic_elongation_m[b] = 0.02 * sim.mesh().rest_length_m[b];
    sim.refresh_rates();
    sim.start_compression();
    Plates& plates = sim.mutable_state().plates;
    plates.top_z_m -= p.plate_gap_m + 2e-6;
    plates.bottom_z_m += 2e-6;
    sim.refresh_rates();
  }
  Params p;
  Tissue tissue;
  Simulation sim;
};

// One term's forces on the wall at positions x (a copy of the state; the fluid's pressures held as they are).
Eigen::VectorXd term_forces(ForceTerm& term, const Simulation& sim, const Eigen::Matrix3Xd& x) {
  State s = sim.state();
  s.wall.x = x;
  const WallSurface surface = wall_surface(x, sim.mesh());
  const ForceContext now = sim.force_context();
  const ForceContext at{{surface, now.fluid.neighbours, now.fluid.cells, now.fluid.eos, now.fluid.Lp_m_per_s_Pa, 1},
                        now.ramp, now.ramp_rate_1_s, false};
  Eigen::Matrix3Xd f = Eigen::Matrix3Xd::Zero(3, x.cols());
  EnergyValues power{};
  term.add_forces(s, at, f, power);
  return Eigen::Map<const Eigen::VectorXd>(f.data(), f.size());
}

}  // namespace

// The leapfrog's forces, the energy account and the stiffness are three loops over the one list: a term
// added to it appears in each, and in the powers.
TEST(ForceField, ATermAddedToTheListIsInItsForcesEnergyPowersAndStiffness) {
  SqueezedCell c;
  const State& s = c.sim.state();
  const ForceContext now = c.sim.force_context();
  ForceField field;
  field.add(std::make_unique<SpringToOrigin>(2.0));
  Eigen::Matrix3Xd force;
  EnergyValues power{};
  PhaseTimer timer;
  timer.start();
  State copy = s;
  field.forces(copy, now, force, power, timer);
  EXPECT_TRUE(force.isApprox(-2.0 * s.wall.x));
  EXPECT_EQ(power[kPlateWork], 1.5);
  const EnergyValues e = field.energy(s, now);
  EXPECT_DOUBLE_EQ(e[kPlateSprings], s.wall.x.squaredNorm());
  EXPECT_EQ(e[kPlasticLoss], s.energy.integral[kPlasticLoss]);  // the running integrals come through
  BlockStiffness K(s.wall.x.cols(), c.sim.mesh().bonds);
  field.stiffness(s, now, K);
  EXPECT_DOUBLE_EQ(Eigen::MatrixXd(K.matrix()).trace(), 2.0 * static_cast<double>(s.wall.x.size()));
}

// The case's field lists each law once, in the order of the forces' sum; a tissue adds its contacts.
TEST(ForceField, TheCasesFieldListsEachLawOnceInTheForcesOrder) {
  SqueezedCell c;
  std::string phases;
  for (const auto& term : c.sim.force_field().terms()) phases += std::to_string(static_cast<int>(term->phase())) + " ";
  const auto phase = [](Phase p) { return std::to_string(static_cast<int>(p)) + " "; };
  EXPECT_EQ(phases, phase(Phase::WallBonds) + phase(Phase::Bending) + phase(Phase::WallFluid) + phase(Phase::Plates));
  const Params two = small_cell_case({{"tissue", {{"cells_x", 2}}}});
  const Simulation tissue(two, build_tissue(two));
  EXPECT_EQ(tissue.force_field().terms().size(), 5u);
  EXPECT_EQ(tissue.force_field().terms()[2]->phase(), Phase::CellContact);
}

// Each term whose stiffness is exact, -dF/dx at its history and the fluid's pressures held: the springs with
// their plastic elongations, the closed cell's follower pressure and the plates, against the central
// difference of the term's own forces, to 1e-6 of the column's size. (The bending's Gauss-Newton part and
// the contacts' stiffness without their sideways part are bounds, tested in test_bending.cpp and
// test_tissue.cpp.)
TEST(ForceField, EachExactStiffnessIsMinusTheCentralDifferenceOfItsTermsForces) {
  SqueezedCell c;
  const Simulation& sim = c.sim;
  const Eigen::Matrix3Xd& x = sim.state().wall.x;
  int plate_columns = 0;
  for (const auto& term : sim.force_field().terms()) {
    const Phase phase = term->phase();
    if (phase == Phase::Bending) continue;
    BlockStiffness stiffness(x.cols(), sim.mesh().bonds);
    stiffness.set_zero();
    ASSERT_TRUE(term->add_stiffness(sim.state(), sim.force_context(), stiffness));
    const Eigen::MatrixXd K = Eigen::MatrixXd(stiffness.matrix());
    ASSERT_GT(K.cwiseAbs().maxCoeff(), 0.0) << "phase " << static_cast<int>(phase);
    const double h = 1e-12;
    for (Eigen::Index j = 0; j < x.size(); j += phase == Phase::Plates ? 1 : 7) {  // few particles touch a plate
      Eigen::Matrix3Xd plus = x, minus = x;
      plus(j % 3, j / 3) += h;
      minus(j % 3, j / 3) -= h;
      const Eigen::VectorXd fd = -(term_forces(*term, sim, plus) - term_forces(*term, sim, minus)) / (2 * h);
      const double scale = std::max(fd.cwiseAbs().maxCoeff(), K.col(j).cwiseAbs().maxCoeff());
      if (scale == 0) continue;  // a particle no plate touches, along the plates' term
      if (phase == Phase::Plates) ++plate_columns;
      EXPECT_LT((K.col(j) - fd).cwiseAbs().maxCoeff(), 1e-6 * scale)
          << "phase " << static_cast<int>(phase) << ", column " << j;
    }
  }
  EXPECT_GT(plate_columns, 0);  // the plates touched some particles
}

// The fluid's faces: SPH has no quasi-static face, and the quasi-static scheme refuses a fluid without one;
// the closed cell has it.
TEST(ForceField, OnlyAFluidWithIncrementsHasTheQuasiStaticFace) {
  const Params sph = small_cell_case();
  Simulation particles(sph, build_tissue(sph));
  EXPECT_EQ(particles.fluid_increments(), nullptr);
  EXPECT_THROW(QuasiStaticScheme scheme(particles), std::logic_error);
  SqueezedCell c;
  EXPECT_NE(c.sim.fluid_increments(), nullptr);
}
