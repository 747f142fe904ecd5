#pragma once
// A quasi-static lone cell's rigid rotation held at zero (compression.cell_rotation = held).
//
// Between the paper's frictionless plates nothing holds a cell's orientation but its inertia: a dynamic
// cell keeps it over a compression, while a sequence of equilibria (quasi_static.hpp) rolls a cell that
// is not quite round to whichever orientation is softest, 10-30 degrees over a compression to strain 0.2
// (docs/model-closures.md, "The quasi-static cell rolls"). The hold is Eckart's condition on the wall's
// positions x_k against its positions X_k when the compression started,
//     C(x) = sum_k (X_k - Xbar) x x_k = 0,
// three linear equations. Their gradients at particle k are the rigid rotations of the reference,
// lambda x (X_k - Xbar), so the reaction that keeps C = 0 is a torque about the centroid (no net force),
// and it does no work on any motion that keeps C = 0: the energy account is unchanged. A translation
// keeps C, so the cell still slides between the plates.
#include <Eigen/Core>

#include "core/errors.hpp"
#include "core/params.hpp"

namespace cellsim {

class RotationHold {
 public:
  explicit RotationHold(const Eigen::Matrix3Xd& reference);

  // C(x) = sum_k (X_k - Xbar) x x_k [m^2]: zero on the constraint.
  Eigen::Vector3d value(const Eigen::Ref<const Eigen::Matrix3Xd>& x) const;
  // v - A^T (A A^T)^-1 A v, in place: a force's part that can move the cell along the constraint (its rest
  // is the reaction), or a move's part that keeps C. Linear and idempotent.
  void project(Eigen::Matrix3Xd& v) const { project_columns(v); }
  void project(Eigen::Ref<Eigen::VectorXd> v) const {  // v stacked as x_0, y_0, z_0, x_1, ...
    project_columns(Eigen::Map<Eigen::Matrix3Xd>(v.data(), 3, v.size() / 3));
  }

 private:
  void project_columns(Eigen::Ref<Eigen::Matrix3Xd> v) const;

  Eigen::Matrix3Xd arm_;         // X_k - Xbar
  Eigen::Matrix3d inverse_gram_; // (A A^T)^-1, A A^T = sum_k (|X_k - Xbar|^2 I - (X_k - Xbar)(X_k - Xbar)^T)
};

// auto (the default) becomes held for a lone cell in the quasi-static scheme and free otherwise; held is
// refused for several cells (their neighbours hold them, and one hold per cell would be a constraint of
// our own making on the tissue's mechanics).
inline void resolve_cell_rotation(Params& p) {
  const bool lone_cell = p.cells_x * p.cells_y * p.cells_z == 1;
  if (p.cell_rotation == kRotationAuto)
    p.cell_rotation = lone_cell && p.time_scheme == kQuasiStatic ? kRotationHeld : kRotationFree;
  else if (p.cell_rotation == kRotationHeld && !lone_cell)
    throw InputError("compression.cell_rotation = held: only a lone cell's rotation can be held (this case has " +
                     std::to_string(p.cells_x * p.cells_y * p.cells_z) +
                     " cells, which hold each other); give free or auto");
}

}  // namespace cellsim
