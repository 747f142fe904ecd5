#pragma once
// Loops that add each item's share to particles other items share too, where the items are not
// near their targets in index (the wall-fluid pairs: fluid rows add to wall particles anywhere), on
// several threads. With one thread the items add straight into the target.
// With T threads the items are cut into T fixed blocks; block b adds into its own zeroed copy, and
// the copies are then added to the target in block order, each column by one thread. The sums thus
// depend on T only (bit-identical for the same thread count, round-off apart between counts).
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "parallel/threads.hpp"

namespace cellsim {

template <class Matrix>
class BlockSums {
 public:
  // scatter(block, begin, end, out) adds the shares of items [begin, end) to out (target-shaped);
  // block is 0 .. threads - 1 (0 with one thread), for per-block partial results of the caller's.
  template <class Scatter>
  void add(int threads, Eigen::Index n_items, Matrix& target, Scatter&& scatter) {
    if (threads <= 1) {
      scatter(0, Eigen::Index{0}, n_items, target);
      return;
    }
    copies_.resize(static_cast<std::size_t>(threads));
    run_on_threads(threads, [&](int t, int count) {
      for (int b = t; b < threads; b += count) {  // blocks are fixed by `threads`, not by the team
        Matrix& copy = copies_[static_cast<std::size_t>(b)];
        copy.setZero(target.rows(), target.cols());
        scatter(b, block_start(n_items, b, threads), block_start(n_items, b + 1, threads), copy);
      }
      wait_for_all_threads();
      const Eigen::Index columns = target.size() / target.rows(), first = block_start(columns, t, count),
                         width = block_start(columns, t + 1, count) - first;
      for (const Matrix& copy : copies_) columns_of(target, first, width) += columns_of(copy, first, width);
    });
  }

 private:
  template <class M>
  static auto columns_of(M& m, Eigen::Index first, Eigen::Index width) {
    if constexpr (std::decay_t<M>::ColsAtCompileTime == 1)
      return m.segment(first, width);
    else
      return m.middleCols(first, width);
  }

  std::vector<Matrix> copies_;
};

}  // namespace cellsim
