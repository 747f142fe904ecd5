// The force field's terms (force_terms.hpp): each face delegates to its law in physics/.
#include "engine/force_terms.hpp"

#include <cmath>

#include "engine/energy_account.hpp"
#include "engine/measures.hpp"
#include "engine/periodic_slab.hpp"
#include "parallel/cell_blocks.hpp"
#include "physics/cavity_pressure.hpp"
#include "physics/wall_stiffness.hpp"

namespace cellsim {
namespace {

// Adds the push on wall particles [begin, end) to their forces, and returns the sum of their push along
// their unit normals (packed norms and divisions), for the wall pressure.
double add_push(const Eigen::Matrix3Xd& on_wall, const Eigen::Matrix3Xd& vertex_normal, Eigen::Index begin,
                Eigen::Index end, Eigen::Matrix3Xd& wall_force) {
  const Eigen::Index count = end - begin;
  wall_force.middleCols(begin, count) += on_wall.middleCols(begin, count);
  return (on_wall.middleCols(begin, count).cwiseProduct(vertex_normal.middleCols(begin, count)).colwise().sum().array() /
          vertex_normal.middleCols(begin, count).colwise().norm().array())
      .sum();
}

}  // namespace

void WallSpringsTerm::add_forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W) {
  const BondSums bonds =
      add_bond_forces(s.wall, mesh_, law_, c.ramp, c.fluid.threads, s.bond_plastic_elongation_m, wall_force, scratch_);
  s.energy.integral[kPlasticLoss] += bonds.plastic_loss_J;  // at fixed positions: a jump, not a rate
  s.wall_tension_N_m = bonds.tension_times_length / (2.0 * c.fluid.surface.area_m2);
  power_W[kDampingLoss] = bonds.damping_loss_W;
  // The drying ramp moves P_T and L_ref (drying.hpp): the stored energy changes at fixed particles.
  const double drying_share = (1.0 - dryness_) * c.ramp_rate_1_s;  // d/dt of (1 - X) ramp
  power_W[kDrive] = c.ramp_rate_1_s == 0 ? 0.0
                                          : drive_power_W(fluid_.stored_energy_per_turgor_m3(s, c.fluid.eos),
                                                          -turgor_Pa_ * drying_share, bonds.contraction_times_l0_N_m,
                                                          contraction_ratio_ * drying_share);
}

void WallSpringsTerm::add_energy(const State& s, const ForceContext& c, EnergyValues& e) const {
  const BondEnergy bonds = bond_energy(s.wall, mesh_, law_, c.ramp, s.bond_plastic_elongation_m);
  e[kWallStiff] = bonds.stiff_J;
  e[kWallContraction] = bonds.contraction_J;
}

bool WallSpringsTerm::add_stiffness(const State& s, const ForceContext& c, BlockStiffness& K) const {
  add_wall_spring_stiffness(s.wall.x, mesh_, law_, c.ramp, s.bond_plastic_elongation_m, K);
  return true;
}

void BendingTerm::add_forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues&) {
  bending_.add_forces(s.wall.x, c.fluid.surface.triangles, c.fluid.threads, wall_force);
}

void BendingTerm::add_energy(const State& s, const ForceContext&, EnergyValues& e) const {
  e[kWallBending] = bending_.energy(s.wall.x);
}

bool BendingTerm::add_stiffness(const State& s, const ForceContext&, BlockStiffness& K) const {
  bending_.add_gauss_newton_stiffness(s.wall.x, Bending::FarCorners::OnBonds, K);
  return true;
}

void CellContactTerm::add_forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues&) {
  Eigen::Vector2d period_virial_J;
  add_cell_contact_forces(s.wall.x, c.fluid.neighbours.wall_wall(), lamella_, law_, s.box, s.lamella_intact,
                          s.lamella_peak_opening_m, wall_force, &period_virial_J);
  if (s.box.periodic()) {
    const Eigen::Vector2d stress = lateral_stress_Pa(period_virial_J, s.box, cell_height_m(s.wall.x));
    s.lateral_stress_x_Pa = stress.x();
    s.lateral_stress_y_Pa = stress.y();
  }
}

void CellContactTerm::add_energy(const State& s, const ForceContext& c, EnergyValues& e) const {
  const CellContactEnergy between = cell_contact_energy(s.wall.x, c.fluid.neighbours.wall_wall(), lamella_, law_, s.box,
                                                        s.lamella_intact, s.lamella_peak_opening_m);
  e[kContact] = between.contact_J;
  e[kLamella] = between.lamella_J;
  e[kLamellaLoss] = between.lamella_dissipated_J;
}

bool CellContactTerm::add_stiffness(const State& s, const ForceContext& c, BlockStiffness& K) const {
  add_cell_contact_stiffness(s.wall.x, c.fluid.neighbours.wall_wall(), lamella_, law_, s.box, s.lamella_intact,
                             s.lamella_peak_opening_m, K);
  return true;
}

void FluidPushTerm::add_forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W) {
  fluid_.couple_to_wall(s, c.fluid, c.pairs_fresh, on_wall_, backstop_on_wall_, power_W);
  const WallSurface& surface = c.fluid.surface;
  const std::vector<double> outward = sum_by_cell(c.fluid.threads, c.fluid.cells.wall, [&](Eigen::Index begin, Eigen::Index end) {
    return add_push(on_wall_, surface.vertex_normal, begin, end, wall_force);
  });
  cell_wall_pressure_Pa_.resize(outward.size());
  double outward_sum = 0;
  for (std::size_t cell = 0; cell < outward.size(); ++cell) {
    cell_wall_pressure_Pa_[cell] = outward[cell] / surface.cell_area_m2[cell];
    outward_sum += outward[cell];
  }
  s.wall_pressure_Pa = outward_sum / surface.area_m2;
}

void FluidPushTerm::add_energy(const State& s, const ForceContext& c, EnergyValues& e) const {
  fluid_.stored_energy(s, c.fluid, e);
}

// The closed cells' pressures turn with the wall (cavity_pressure.hpp); a fluid of particles pushes through
// pairs the quasi-static scheme does not solve.
bool FluidPushTerm::add_stiffness(const State& s, const ForceContext& c, BlockStiffness& K) const {
  if (!increments_) return false;
  add_pressure_follower_stiffness(s.wall.x, mesh_, fluid_.cell_mean_pressure_Pa(c.fluid.cells), K);
  return true;
}

void PlatesTerm::add_forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W) {
  Plates& plates = s.plates;
  power_W[kPlateWork] = 0;
  if (!plates.active) return;
  add_plate_forces(s.wall.x, law_, plates, wall_force, c.fluid.threads);
  // The wall pushes up; the plate moves down (negative speed while it unloads).
  power_W[kPlateWork] = plates.force_top_N * top_plate_speed_m_s(plates, motion_);
  if (std::isnan(plates.first_contact_top_z_m) && plates.force_top_N > 0) plates.first_contact_top_z_m = plates.top_z_m;
}

void PlatesTerm::add_energy(const State& s, const ForceContext&, EnergyValues& e) const {
  e[kPlateSprings] = plate_energy_J(s.wall.x, law_, s.plates);
}

bool PlatesTerm::add_stiffness(const State& s, const ForceContext&, BlockStiffness& K) const {
  add_plate_stiffness(s.wall.x, law_, s.plates, K);
  return true;
}

}  // namespace cellsim
