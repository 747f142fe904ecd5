#include "geometry/block_stiffness.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cellsim {

BlockStiffness::BlockStiffness(Eigen::Index particles, const std::vector<std::array<int, 2>>& pairs)
    : matrix_(3 * particles, 3 * particles), rows_of_column_(static_cast<std::size_t>(particles)) {
  for (Eigen::Index b = 0; b < particles; ++b)
    rows_of_column_[static_cast<std::size_t>(b)].push_back(static_cast<int>(b));
  for (const auto& [a, b] : pairs) {
    if (a == b || a < 0 || b < 0 || a >= particles || b >= particles)
      throw std::logic_error("BlockStiffness: pair (" + std::to_string(a) + ", " + std::to_string(b) +
                             ") is not a pair of its particles");
    rows_of_column_[static_cast<std::size_t>(b)].push_back(a);
    rows_of_column_[static_cast<std::size_t>(a)].push_back(b);
  }
  Eigen::Index entries = 0;
  for (auto& rows : rows_of_column_) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    entries += 9 * static_cast<Eigen::Index>(rows.size());
  }
  // Column 3b + c holds the rows 3a + r of every a joined to b (b itself too), in order; so block (a, b)'s
  // column c starts 3 x (a's place among them) into column 3b + c.
  matrix_.resizeNonZeros(entries);
  int* outer = matrix_.outerIndexPtr();
  int* inner = matrix_.innerIndexPtr();
  Eigen::Index at = 0;
  for (Eigen::Index b = 0; b < particles; ++b)
    for (int c = 0; c < 3; ++c) {
      outer[3 * b + c] = static_cast<int>(at);
      for (int a : rows_of_column_[static_cast<std::size_t>(b)])
        for (int r = 0; r < 3; ++r) inner[at++] = 3 * a + r;
    }
  outer[3 * particles] = static_cast<int>(at);
  set_zero();
}

void BlockStiffness::set_zero() { std::fill_n(matrix_.valuePtr(), matrix_.nonZeros(), 0.0); }

Eigen::Index BlockStiffness::slot(int a, int b) const {
  const std::vector<int>& rows = rows_of_column_[static_cast<std::size_t>(b)];
  const auto found = std::lower_bound(rows.begin(), rows.end(), a);
  if (found == rows.end() || *found != a)
    throw std::logic_error("BlockStiffness: no block joins particles " + std::to_string(a) + " and " +
                           std::to_string(b));
  return matrix_.outerIndexPtr()[3 * b] + 3 * (found - rows.begin());
}

void BlockStiffness::add_pair(int a, int b, const Eigen::Matrix3d& block) {
  add(a, a, block);
  add(b, b, block);
  add(a, b, -block);
  add(b, a, -block);
}

bool BlockStiffness::joins(int a, int b) const {
  const std::vector<int>& rows = rows_of_column_[static_cast<std::size_t>(b)];
  return std::binary_search(rows.begin(), rows.end(), a);
}

void BlockStiffness::add(int a, int b, const Eigen::Matrix3d& block) {
  const Eigen::Index first = slot(a, b);
  const Eigen::Index column_length = 3 * static_cast<Eigen::Index>(rows_of_column_[static_cast<std::size_t>(b)].size());
  double* values = matrix_.valuePtr();
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) values[first + c * column_length + r] += block(r, c);
}

}  // namespace cellsim
