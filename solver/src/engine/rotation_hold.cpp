#include "engine/rotation_hold.hpp"

#include <stdexcept>
#include <string>

#include <Eigen/Geometry>  // cross products
#include <Eigen/LU>        // the 3 x 3 inverse and determinant

namespace cellsim {

RotationHold::RotationHold(const Eigen::Matrix3Xd& reference) : arm_(reference.colwise() - reference.rowwise().mean()) {
  Eigen::Matrix3d gram = Eigen::Matrix3d::Zero();
  for (Eigen::Index k = 0; k < arm_.cols(); ++k)
    gram += arm_.col(k).squaredNorm() * Eigen::Matrix3d::Identity() - arm_.col(k) * arm_.col(k).transpose();
  // Singular only where every particle sits on one line: no cell.
  if (!(gram.determinant() > 0)) throw std::logic_error("RotationHold: the reference's particles lie on a line");
  inverse_gram_ = gram.inverse();
}

Eigen::Vector3d RotationHold::value(const Eigen::Ref<const Eigen::Matrix3Xd>& x) const {
  if (x.cols() != arm_.cols())
    throw std::logic_error("RotationHold: " + std::to_string(x.cols()) + " particles against a reference of " +
                           std::to_string(arm_.cols()));
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (Eigen::Index k = 0; k < arm_.cols(); ++k) c += arm_.col(k).cross(x.col(k));
  return c;
}

void RotationHold::project_columns(Eigen::Ref<Eigen::Matrix3Xd> v) const {
  const Eigen::Vector3d lambda = inverse_gram_ * value(v);
  for (Eigen::Index k = 0; k < arm_.cols(); ++k) v.col(k) -= lambda.cross(arm_.col(k));
}

}  // namespace cellsim
