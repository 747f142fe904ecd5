#pragma once
// Eigen arrays to and from HDF5: particle fields as N x 3 (positions, velocities) or N datasets.
#include <string>

#include <Eigen/Core>

#include "io/h5.hpp"

namespace cellsim::h5 {

// Matrix3Xd is column-major, so its memory is already the row-major N x 3 layout.
inline void write_points(hid_t parent, const std::string& name, const Eigen::Matrix3Xd& m) {
  write(parent, name, std::vector<double>(m.data(), m.data() + m.size()), {static_cast<hsize_t>(m.cols()), 3});
}

inline void write_values(hid_t parent, const std::string& name, const Eigen::VectorXd& v) {
  write(parent, name, std::vector<double>(v.data(), v.data() + v.size()), {static_cast<hsize_t>(v.size())});
}

inline Eigen::Matrix3Xd read_points(hid_t parent, const std::string& name) {
  std::vector<hsize_t> dims;
  const auto data = read_doubles(parent, name, &dims);
  if (dims.size() != 2 || dims[1] != 3) throw std::runtime_error(name + " is not an N x 3 array");
  return Eigen::Map<const Eigen::Matrix3Xd>(data.data(), 3, static_cast<Eigen::Index>(dims[0]));
}

inline Eigen::VectorXd read_values(hid_t parent, const std::string& name) {
  const auto data = read_doubles(parent, name);
  return Eigen::Map<const Eigen::VectorXd>(data.data(), static_cast<Eigen::Index>(data.size()));
}

}  // namespace cellsim::h5
