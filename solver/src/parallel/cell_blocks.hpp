#pragma once
// Loops over a tissue's particles cell by cell (model.md §10). The particles are cut into the blocks
// of threads.hpp as in every other loop, and each block again where a cell ends, so that a piece of
// work sees the particles of one cell only. first[c] is cell c's first particle; first.back() = n.
#include <vector>

#include <Eigen/Core>

#include "parallel/threads.hpp"

namespace cellsim {

// work(c, begin, end) for each piece: [begin, end) within cell c.
template <class Work>
void for_cell_blocks(int threads, const std::vector<Eigen::Index>& first, Work&& work) {
  for_blocks(threads, first.back(), [&](Eigen::Index begin, Eigen::Index end) {
    for (int c = 0; c + 1 < static_cast<int>(first.size()); ++c) {
      const Eigen::Index from = std::max(begin, first[c]), to = std::min(end, first[c + 1]);
      if (from < to) work(c, from, to);
    }
  });
}

// Each cell's sum of part(begin, end) over its pieces, the blocks added in block order (one cell:
// the same sum as reduce_blocks over all particles).
template <class Part>
std::vector<double> sum_by_cell(int threads, const std::vector<Eigen::Index>& first, Part&& part) {
  const std::size_t cells = first.size() - 1;
  return reduce_blocks<std::vector<double>>(
      threads, first.back(),
      [&](Eigen::Index begin, Eigen::Index end) {
        std::vector<double> sums(cells, 0.0);
        for (std::size_t c = 0; c < cells; ++c) {
          const Eigen::Index from = std::max(begin, first[c]), to = std::min(end, first[c + 1]);
          if (from < to) sums[c] = part(from, to);
        }
        return sums;
      },
      [](std::vector<double> a, const std::vector<double>& b) {
        for (std::size_t c = 0; c < a.size(); ++c) a[c] += b[c];
        return a;
      });
}

}  // namespace cellsim
