#pragma once
// Cubic B-spline kernel, Eq 5 with the paper's typos fixed (model.md §2): support 2h,
// W = 3/(2 pi h^3) {2/3 - s^2 + s^3/2 (s<1); (2-s)^3/6 (1<=s<2); 0}, s = r/h.
#include <cmath>

namespace cellsim {

class CubicSplineKernel {
 public:
  explicit CubicSplineKernel(double h) : h_(h), inv_h_(1.0 / h), norm_(3.0 / (2.0 * M_PI * h * h * h)) {}

  double h() const { return h_; }
  double support() const { return 2.0 * h_; }

  double W(double r) const {
    const double s = r * inv_h_;
    if (s < 1.0) return norm_ * (2.0 / 3.0 - s * s + 0.5 * s * s * s);
    if (s < 2.0) {
      const double t = 2.0 - s;
      return norm_ * t * t * t / 6.0;
    }
    return 0.0;
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

  // (1/r) dW/dr, finite at r -> 0, as the pair forces need it.
  double dW_dr_over_r(double r) const {
    const double s = r * inv_h_;
    if (s < 1.0) return norm_ * inv_h_ * inv_h_ * (-2.0 + 1.5 * s);
    if (s < 2.0) {
      const double t = 2.0 - s;
      return -norm_ * inv_h_ * 0.5 * t * t / r;
    }
    return 0.0;
  }

 private:
  double h_, inv_h_, norm_;
};

}  // namespace cellsim
