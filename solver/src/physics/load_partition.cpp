#include "physics/load_partition.hpp"

namespace cellsim {

LoadPartition top_plate_load(const Eigen::Matrix3Xd& wall_x, const Eigen::Matrix3Xd& wall_force,
                             const Eigen::Matrix3Xd& coupling_on_wall, const Eigen::Matrix3Xd& backstop_on_wall,
                             const PlateLaw& law, const Plates& plates) {
  LoadPartition out;
  if (!plates.active || wall_force.cols() != wall_x.cols() || coupling_on_wall.cols() != wall_x.cols()) return out;
  const bool backstop = backstop_on_wall.cols() == wall_x.cols();
  for (Eigen::Index k = 0; k < wall_x.cols(); ++k) {
    const PlateOverlap o = plate_overlap(wall_x.col(k), law, plates);
    if (!(o.top_m > 0)) continue;
    // Eq 22 on this particle, taken out of the total: what remains is the coupling and the wall's own.
    const double plate_z = law.stiffness_N_m * (o.bottom_m - o.top_m);
    out.fluid_push_N += coupling_on_wall(2, k);
    if (backstop) out.backstop_push_N += backstop_on_wall(2, k);
    out.wall_push_N += wall_force(2, k) - coupling_on_wall(2, k) - plate_z;
  }
  return out;
}

}  // namespace cellsim
