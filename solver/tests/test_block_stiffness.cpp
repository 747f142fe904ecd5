// The stiffness of 3 x 3 blocks on a fixed pattern (geometry/block_stiffness.hpp): what is added lands
// where a dense matrix puts it, a pair outside the pattern is refused by name, and zeroing keeps the
// pattern.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "geometry/block_stiffness.hpp"

using namespace cellsim;

namespace {

Eigen::Matrix3d random_block(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Matrix3d m;
  for (int i = 0; i < 9; ++i) m(i % 3, i / 3) = u(rng);
  return m;
}

}  // namespace

// Six particles, pairs given in either order and one twice: random blocks on every pair both ways and on
// the diagonal, each added twice, equal the dense sum exactly; the stored entries are the pattern's 9 x
// (6 + 2 x 5), none more.
TEST(BlockStiffness, AddsEveryBlockWhereTheDenseMatrixHasIt) {
  const std::vector<std::array<int, 2>> pairs = {{0, 1}, {2, 1}, {1, 2}, {3, 5}, {4, 0}, {5, 2}};
  BlockStiffness K(6, pairs);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(18, 18);
  std::mt19937 rng(5);
  std::vector<std::array<int, 2>> blocks;
  for (int a = 0; a < 6; ++a) blocks.push_back({a, a});
  for (const auto& [a, b] : pairs) {
    blocks.push_back({a, b});
    blocks.push_back({b, a});
  }
  for (int twice = 0; twice < 2; ++twice)
    for (const auto& [a, b] : blocks) {
      const Eigen::Matrix3d block = random_block(rng);
      K.add(a, b, block);
      dense.block<3, 3>(3 * a, 3 * b) += block;
    }
  EXPECT_EQ(K.matrix().nonZeros(), 9 * (6 + 2 * 5));
  EXPECT_EQ((Eigen::MatrixXd(K.matrix()) - dense).cwiseAbs().maxCoeff(), 0.0);
  K.set_zero();
  EXPECT_EQ(K.matrix().nonZeros(), 9 * (6 + 2 * 5));
  EXPECT_EQ(Eigen::MatrixXd(K.matrix()).cwiseAbs().maxCoeff(), 0.0);
}

TEST(BlockStiffness, RefusesABlockOutsideItsPatternNamingThePair) {
  BlockStiffness K(4, {{0, 1}, {1, 2}});
  try {
    K.add(0, 3, Eigen::Matrix3d::Identity());
    FAIL() << "a block of two particles no pair joins was taken";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("particles 0 and 3"), std::string::npos) << e.what();
  }
  EXPECT_THROW(BlockStiffness(4, {{2, 2}}), std::logic_error);
  EXPECT_THROW(BlockStiffness(4, {{0, 4}}), std::logic_error);
}
