#include "engine/strain_gauge.hpp"

#include <cmath>
#include <limits>

namespace cellsim {

LayerHeights layer_heights(const Eigen::Matrix3Xd& wall_x, const CellRanges& cells) {
  LayerHeights h;
  const int layers = cells.layers();
  std::vector<int> count(static_cast<std::size_t>(layers), 0);
  h.layer_centroid_z_m.assign(static_cast<std::size_t>(layers), 0.0);
  h.layer_height_m.assign(static_cast<std::size_t>(layers), 0.0);
  for (int c = 0; c < cells.count(); ++c) {
    const auto z = wall_x.row(2).segment(cells.wall[c], cells.wall_count(c));
    h.cell_centroid_z_m.push_back(z.mean());
    h.cell_height_m.push_back(z.maxCoeff() - z.minCoeff());
    const auto layer = static_cast<std::size_t>(cells.layer_of(c));
    h.layer_centroid_z_m[layer] += h.cell_centroid_z_m.back();
    h.layer_height_m[layer] += h.cell_height_m.back();
    ++count[layer];
  }
  for (std::size_t k = 0; k < count.size(); ++k) {
    h.layer_centroid_z_m[k] /= count[k];
    h.layer_height_m[k] /= count[k];
  }
  return h;
}

double gauge_length_m(const std::vector<double>& z) {
  const std::size_t n = z.size();
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  return n >= 4 ? z[n - 2] - z[1] : z[n - 1] - z[0];
}

}  // namespace cellsim
