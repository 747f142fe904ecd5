#include "physics/plates.hpp"

#include <cmath>

#include "parallel/threads.hpp"

namespace cellsim {

PlateLaw plate_law(const Params& p) {
  if (p.lateral != kLateralFree)  // a periodic slab: the plates cover every period (model.md §10b)
    return {p.plate_range_m, p.plate_stiffness_N_m, INFINITY, INFINITY};
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

double plate_energy_J(const Eigen::Matrix3Xd& wall_x, const PlateLaw& law, const Plates& plates) {
  if (!plates.active) return 0.0;
  double e = 0;
  for (Eigen::Index k = 0; k < wall_x.cols(); ++k) {
    const PlateOverlap o = plate_overlap(wall_x.col(k), law, plates);
    e += 0.5 * law.stiffness_N_m * (o.top_m * o.top_m + o.bottom_m * o.bottom_m);
  }
  return e;
}

namespace {

struct PlateLoad {
  double top_N = 0, bottom_N = 0;
  int contacts = 0;
  PlateLoad plus(const PlateLoad& later) const {
    return {top_N + later.top_N, bottom_N + later.bottom_N, contacts + later.contacts};
  }
};

// Wall particles [begin, end): Eq 22 added to their forces; returns the load they put on the plates.
PlateLoad add_block(const Eigen::Matrix3Xd& wall_x, const PlateLaw& law, const Plates& plates, Eigen::Index begin,
                    Eigen::Index end, Eigen::Matrix3Xd& wall_force) {
  PlateLoad load;
  for (Eigen::Index k = begin; k < end; ++k) {
    const PlateOverlap o = plate_overlap(wall_x.col(k), law, plates);
    if (o.top_m > 0) {
      const double f = law.stiffness_N_m * o.top_m;
      wall_force(2, k) -= f;  // pushed down, away from the top plate
      load.top_N += f;
      ++load.contacts;
    }
    if (o.bottom_m > 0) {
      const double f = law.stiffness_N_m * o.bottom_m;
      wall_force(2, k) += f;
      load.bottom_N += f;
      ++load.contacts;
    }
  }
  return load;
}

}  // namespace

void add_plate_forces(const Eigen::Matrix3Xd& wall_x, const PlateLaw& law, Plates& plates, Eigen::Matrix3Xd& wall_force,
                      int threads) {
  const PlateLoad load = reduce_blocks<PlateLoad>(
      threads, wall_x.cols(),
      [&](Eigen::Index begin, Eigen::Index end) { return add_block(wall_x, law, plates, begin, end, wall_force); },
      [](const PlateLoad& a, const PlateLoad& b) { return a.plus(b); });
  plates.force_top_N = load.top_N;
  plates.force_bottom_N = load.bottom_N;
  plates.contacts = load.contacts;
}

void add_plate_stiffness(const Eigen::Matrix3Xd& wall_x, const PlateLaw& law, const Plates& plates, BlockStiffness& K) {
  if (!plates.active) return;
  const Eigen::Matrix3d along_z = Eigen::Vector3d(0, 0, law.stiffness_N_m).asDiagonal();
  for (int k = 0; k < static_cast<int>(wall_x.cols()); ++k)
    if (plate_overlap(wall_x.col(k), law, plates).touches()) K.add(k, k, along_z);
}

}  // namespace cellsim
