// Where a quasi-static increment's relaxation starts (increment_predictor.hpp).
#include "engine/increment_predictor.hpp"

namespace cellsim {

void keep_plate_overlaps(Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& was_x, const PlateLaw& law,
                         const Plates& before, const Plates& after) {
  if (!after.active) return;
  for (Eigen::Index k = 0; k < x.cols(); ++k) {  // column k of was_x is read before x's is written
    const PlateOverlap was = before.active ? plate_overlap(was_x.col(k), law, before) : PlateOverlap{};
    const PlateOverlap now = plate_overlap(x.col(k), law, after);
    if (now.top_m > was.top_m) x(2, k) -= now.top_m - was.top_m;
    if (now.bottom_m > was.bottom_m) x(2, k) += now.bottom_m - was.bottom_m;
  }
}

Eigen::Matrix3Xd secant_motion(const Eigen::Matrix3Xd& increment_motion_m) {
  Eigen::Matrix3Xd motion = increment_motion_m;
  motion.topRows<2>().colwise() -= motion.topRows<2>().rowwise().mean();
  return motion;
}

}  // namespace cellsim
