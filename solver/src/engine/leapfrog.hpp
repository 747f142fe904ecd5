#pragma once
// The leapfrog's per-column updates (model.md §7), shared by the wall's and the fluid's kicks and drifts.
// Functions of their own, with the scalars as value parameters: inside a lambda that other threads also
// run, the compiler would re-read them after every store and not vectorise.
#include <algorithm>

#include <Eigen/Core>

namespace cellsim {

// y += factor * rate, for columns [begin, end) (a kick, or a drift).
inline void add_scaled(double factor, const Eigen::Matrix3Xd& rate, Eigen::Index begin, Eigen::Index end,
                       Eigen::Matrix3Xd& y) {
  y.middleCols(begin, end - begin) += factor * rate.middleCols(begin, end - begin);
}

// The drift of columns [begin, end), x += dt v; returns the largest |v|^2, read 256 columns at a time
// while they are still in cache (the bound on how far the step moved the particles).
inline double drift_columns(double dt, const Eigen::Matrix3Xd& v, Eigen::Index begin, Eigen::Index end,
                            Eigen::Matrix3Xd& x) {
  constexpr Eigen::Index kChunk = 256;
  double v2 = 0;
  for (Eigen::Index c0 = begin; c0 < end; c0 += kChunk) {
    const Eigen::Index c1 = std::min(c0 + kChunk, end);
    add_scaled(dt, v, c0, c1, x);
    v2 = std::max(v2, v.middleCols(c0, c1 - c0).colwise().squaredNorm().maxCoeff());
  }
  return v2;
}

}  // namespace cellsim
