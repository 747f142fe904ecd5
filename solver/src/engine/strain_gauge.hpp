#pragma once
// The interior strain gauge of a layered tissue (model.md §10c): the plates' nominal strain includes
// the half cells they flatten; the gauge reads the strain of the layers away from them, from the
// heights of the layers' centroid planes.
#include <vector>

#include <Eigen/Core>

#include "geometry/tissue.hpp"

namespace cellsim {

struct LayerHeights {
  std::vector<double> cell_centroid_z_m, cell_height_m;    // per cell: its wall's mean z and z extent
  std::vector<double> layer_centroid_z_m, layer_height_m;  // per layer: the means over its cells
};

LayerHeights layer_heights(const Eigen::Matrix3Xd& wall_x, const CellRanges& cells);

// The gauge length: the distance between the centroid planes of the lowest and the highest interior
// layer (layers 1 and n - 2) when there are four layers or more; of the bottom and the top layer when
// there are two or three (no two interior layers); NaN for one layer.
double gauge_length_m(const std::vector<double>& layer_centroid_z_m);

}  // namespace cellsim
