// The force field's three loops (force_field.hpp).
#include "engine/force_field.hpp"

#include "parallel/threads.hpp"

namespace cellsim {

void ForceField::forces(State& s, const ForceContext& c, Eigen::Matrix3Xd& wall_force, EnergyValues& power_W,
                        PhaseTimer& timer) const {
  wall_force.resize(3, s.wall.size());
  for_blocks(c.fluid.threads, s.wall.size(), [&](Eigen::Index begin, Eigen::Index end) {
    wall_force.middleCols(begin, end - begin).setZero();
  });
  for (const auto& term : terms_) {
    term->add_forces(s, c, wall_force, power_W);
    timer.lap(term->phase());
  }
}

EnergyValues ForceField::energy(const State& s, const ForceContext& c) const {
  EnergyValues e = s.energy.integral;  // the integrated terms (zero in the others' slots); the terms set theirs
  for (const auto& term : terms_) term->add_energy(s, c, e);
  e[kKinetic] += 0.5 * s.wall.mass_kg * s.wall.v.colwise().squaredNorm().sum();
  return e;
}

void ForceField::stiffness(const State& s, const ForceContext& c, BlockStiffness& K) const {
  K.set_zero();
  for (const auto& term : terms_) term->add_stiffness(s, c, K);
}

}  // namespace cellsim
