#include "plates.hpp"

#include <cmath>

namespace cellsim {

PlateLaw plate_law(const Params& p) {
  return {p.plate_range_m, p.plate_stiffness_N_m, p.plate_length_m, p.plate_width_m};
}

PlateOverlap plate_overlap(const Eigen::Vector3d& x, const PlateLaw& law, const Plates& plates) {
  PlateOverlap o;
  if (std::abs(x.x() - plates.axis_x_m) > 0.5 * law.length_m || std::abs(x.y() - plates.axis_y_m) > 0.5 * law.width_m)
    return o;  // outside the footprint
  const double d_top = plates.top_z_m - x.z(), d_bottom = x.z() - plates.bottom_z_m;
  if (d_top < law.range_m) o.top_m = law.range_m - d_top;
  if (d_bottom < law.range_m) o.bottom_m = law.range_m - d_bottom;
  return o;
}

void add_plate_forces(const Eigen::Matrix3Xd& wall_x, const PlateLaw& law, Plates& plates,
                      Eigen::Matrix3Xd& wall_force) {
  plates.force_top_N = plates.force_bottom_N = 0;
  plates.contacts = 0;
  for (Eigen::Index k = 0; k < wall_x.cols(); ++k) {
    const PlateOverlap o = plate_overlap(wall_x.col(k), law, plates);
    if (o.top_m > 0) {
      const double f = law.stiffness_N_m * o.top_m;
      wall_force(2, k) -= f;  // pushed down, away from the top plate
      plates.force_top_N += f;
      ++plates.contacts;
    }
    if (o.bottom_m > 0) {
      const double f = law.stiffness_N_m * o.bottom_m;
      wall_force(2, k) += f;
      plates.force_bottom_N += f;
      ++plates.contacts;
    }
  }
}

}  // namespace cellsim
