#pragma once
// Cubic B-spline kernel, Eq 5 with the paper's typos fixed (model.md §2): support 2h,
// W = 3/(2 pi h^3) {2/3 - s^2 + s^3/2 (s<1); (2-s)^3/6 (1<=s<2); 0}, s = r/h.
#include <cmath>
#include <cstddef>

#include "parallel/simd4.hpp"

namespace cellsim {

class CubicSplineKernel {
 public:
  explicit CubicSplineKernel(double h) : h_(h), inv_h_(1.0 / h), norm_(3.0 / (2.0 * M_PI * h * h * h)) {}

  double h() const { return h_; }
  double support() const { return 2.0 * h_; }

  // W for one distance (double) or four at once (simd::double4), without branches as below: both
  // pieces evaluated and one selected; max(2 - s, 0) is 2 - s up to s = 2 and exactly 0 beyond.
  template <class T>
  T W(T r) const {
    const T s = r * inv_h_;
    const T inner = norm_ * (2.0 / 3.0 - s * s + 0.5 * s * s * s);
    const T t = simd::max(2.0 - s, 0.0);
    const T outer = norm_ * t * t * t / 6.0;
    return simd::select(s < 1.0, inner, outer);
  }

  // dW/dr (<= 0); the gradient is grad_i W_ij = dW/dr * (x_i - x_j) / r.
  double dW_dr(double r) const {
    const double s = r * inv_h_;
    if (s < 1.0) return norm_ * inv_h_ * (-2.0 * s + 1.5 * s * s);
    if (s < 2.0) {
      const double t = 2.0 - s;
      return -norm_ * inv_h_ * 0.5 * t * t;
    }
    return 0.0;
  }

  // (1/r) dW/dr, finite at r -> 0, as the pair forces need it: for one distance (double) or four
  // at once (simd::double4, the lanes of the pair loop). Written without branches: both pieces
  // are evaluated, clamped so neither can trap, and one is selected; for s >= 1, max(r, h) = r,
  // and max(2 - s, 0) is 2 - s up to s = 2 and 0 beyond the support.
  template <class T>
  T dW_dr_over_r(T r) const {
    const T s = r * inv_h_;
    const T inner = norm_ * inv_h_ * inv_h_ * (-2.0 + 1.5 * s);
    const T t = simd::max(2.0 - s, 0.0);
    const T outer = -norm_ * inv_h_ * 0.5 * t * t / simd::max(r, h_);
    return simd::select(s < 1.0, inner, outer);
  }

 private:
  double h_, inv_h_, norm_;
};

}  // namespace cellsim
