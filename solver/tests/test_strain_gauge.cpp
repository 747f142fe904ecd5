// The interior strain gauge (model.md §10c): which layers it spans, and the layers' mean heights.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/strain_gauge.hpp"

using namespace cellsim;

TEST(StrainGauge, SpansTheInteriorLayersFromFourLayersOnAndTheEndLayersBelow) {
  EXPECT_TRUE(std::isnan(gauge_length_m({1.0})));           // one layer: no gauge
  EXPECT_DOUBLE_EQ(gauge_length_m({1.0, 3.0}), 2.0);         // two: bottom to top
  EXPECT_DOUBLE_EQ(gauge_length_m({1.0, 3.0, 6.0}), 5.0);    // three: still bottom to top
  EXPECT_DOUBLE_EQ(gauge_length_m({1.0, 3.0, 6.0, 10.0}), 3.0);  // four: layers 1 and 2
  EXPECT_DOUBLE_EQ(gauge_length_m({0.0, 3.0, 6.0, 10.0, 15.0}), 7.0);  // five: layers 1 and 3
}

TEST(StrainGauge, LayerHeightsAreTheMeansOfTheirCells) {
  // Two cells in layer 0 and one in layer 1, each two wall particles one above the other.
  CellRanges cells;
  cells.wall = {0, 2, 4, 6};
  cells.fluid = {0, 0, 0, 0};
  cells.layer = {0, 0, 1};
  Eigen::Matrix3Xd x(3, 6);
  x << 0, 0, 5, 5, 0, 0,  //
      0, 0, 0, 0, 0, 0,   //
      0, 2, 1, 5, 10, 11;
  const LayerHeights h = layer_heights(x, cells);
  EXPECT_EQ(h.cell_centroid_z_m, (std::vector<double>{1, 3, 10.5}));
  EXPECT_EQ(h.cell_height_m, (std::vector<double>{2, 4, 1}));
  EXPECT_EQ(h.layer_centroid_z_m, (std::vector<double>{2, 10.5}));
  EXPECT_EQ(h.layer_height_m, (std::vector<double>{3, 1}));
  CellRanges one;  // the single cell: one layer
  one.wall = {0, 6};
  one.fluid = {0, 0};
  EXPECT_EQ(layer_heights(x, one).layer_centroid_z_m.size(), 1u);
}
