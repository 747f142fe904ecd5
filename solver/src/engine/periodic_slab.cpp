#include "engine/periodic_slab.hpp"

#include <algorithm>
#include <sstream>

#include "core/errors.hpp"

namespace cellsim {

Eigen::Vector2d lateral_stress_Pa(const Eigen::Vector2d& period_virial_J, const PeriodicBox& box, double height_m) {
  return -period_virial_J / (box.area_m2() * height_m);
}

double follow_lateral_stress(State& s, const CellRanges& cells, double period_viscosity_Pa_s, double dt,
                             double height_m) {
  const Eigen::Vector2d stress(s.lateral_stress_x_Pa, s.lateral_stress_y_Pa);
  const Eigen::Vector2d strain = -stress / period_viscosity_Pa_s * dt;
  if (strain.cwiseAbs().maxCoeff() > kLargestPeriodStrainPerStep) {  // a period that jumps would tear the slab
    std::ostringstream msg;
    msg << "the period would strain by " << strain.cwiseAbs().maxCoeff() << " in one step (lateral stress "
        << s.lateral_stress_x_Pa / 1e3 << " / " << s.lateral_stress_y_Pa / 1e3
        << " kPa); raise tissue.period_viscosity_Pa_s (now " << period_viscosity_Pa_s << ")";
    throw NumericalFailure(msg.str());
  }
  // The cells move whole, so only the pairs between them change energy: by the virial's work, -W . strain =
  // sigma . strain L_x L_y H (the stress's own definition), which the follower dissipates.
  s.energy.integral[kPeriodLoss] -= stress.dot(strain) * s.box.area_m2() * height_m;
  return strain_period(s, cells, strain);
}

double strain_period(State& s, const CellRanges& cells, const Eigen::Vector2d& strain) {
  double moved_m = 0;
  for (int c = 0; c < cells.count(); ++c) {
    const Eigen::Vector2d centroid = s.wall.x.middleCols(cells.wall[c], cells.wall_count(c)).topRows<2>().rowwise().mean();
    const Eigen::Vector2d by = strain.cwiseProduct(centroid);
    s.wall.x.middleCols(cells.wall[c], cells.wall_count(c)).topRows<2>().colwise() += by;
    s.fluid.x.middleCols(cells.fluid[c], cells.fluid_count(c)).topRows<2>().colwise() += by;
    moved_m = std::max(moved_m, by.norm());
  }
  s.box.length_x_m *= 1.0 + strain.x();
  s.box.length_y_m *= 1.0 + strain.y();
  return moved_m + strain.cwiseAbs().maxCoeff() * std::max(s.box.length_x_m, s.box.length_y_m);
}

}  // namespace cellsim
