#pragma once
// The lateral period of a laterally periodic tissue (model.md §10b): x and y repeat every length_x_m
// and length_y_m; z (between the plates) does not. Each cell keeps its particles in one unwrapped piece,
// so a cell's own sums (its SPH, its wall, its volume and area) never see the period; only the forces
// between cells take the nearest image. A length of 0 means no period along that axis (the cluster).
#include <cmath>

#include <Eigen/Core>

namespace cellsim {

struct PeriodicBox {
  double length_x_m = 0, length_y_m = 0;

  bool periodic() const { return length_x_m > 0; }
  double area_m2() const { return length_x_m * length_y_m; }

  // The nearest image of a separation: each periodic component brought into [-L/2, L/2].
  Eigen::Vector3d nearest_image(Eigen::Vector3d d) const {
    if (length_x_m > 0) d.x() -= length_x_m * std::nearbyint(d.x() / length_x_m);
    if (length_y_m > 0) d.y() -= length_y_m * std::nearbyint(d.y() / length_y_m);
    return d;
  }
};

}  // namespace cellsim
