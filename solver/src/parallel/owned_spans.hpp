#pragma once
// Loops over wall items (bonds, hinges, triangles) that add to their corners, on several threads
// without per-thread copies: thread t owns the targets [n t / T, n (t + 1) / T) (the same particles
// for_blocks gives it) and goes over the items that touch them, adding only to targets it owns.
// An item across the boundary is computed by both threads, each adding its own ends. Every target
// receives its items' shares in item order, as with one thread, so the sums are the same to the bit
// for every thread count; and no thread writes memory another thread writes. The wall's items are
// sorted by their smallest corner and its particles are a spiral, so an item spans few indices and
// the threads' item ranges overlap only near their boundary.
#include <algorithm>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "parallel/threads.hpp"

namespace cellsim {

struct OwnedSpan {
  Eigen::Index item_begin = 0, item_end = 0;  // the items that touch a target in [target_begin, target_end)
  int target_begin = 0, target_end = 0;
  bool all = false;  // it owns every target (one thread): loops drop the checks (with_all_or_some)
  bool owns(int target) const { return target >= target_begin && target < target_end; }
};

// Calls loop(std::true_type) when the span owns every target, loop(std::false_type) otherwise, so
// that a loop written `if (All::value || span.owns(v))` has no checks on one thread.
template <class Loop>
auto with_all_or_some(const OwnedSpan& span, Loop&& loop) {
  return span.all ? loop(std::true_type{}) : loop(std::false_type{});
}

class OwnedSpans {
 public:
  // targets_of(item) gives an item's targets (any container of ints). Computed again only when the
  // thread count or the sizes change: keep one OwnedSpans per loop of one mesh.
  template <class TargetsOf>
  const std::vector<OwnedSpan>& for_threads(int threads, int n_targets, Eigen::Index n_items, TargetsOf&& targets_of) {
    if (threads == threads_ && n_targets == n_targets_ && n_items == n_items_) return spans_;
    threads_ = threads, n_targets_ = n_targets, n_items_ = n_items;
    if (threads == 1) {
      spans_.assign(1, OwnedSpan{0, n_items, 0, n_targets, true});
      return spans_;
    }
    spans_.assign(static_cast<std::size_t>(threads), OwnedSpan{});
    for (int t = 0; t < threads; ++t) {
      auto& s = spans_[static_cast<std::size_t>(t)];
      s.item_begin = n_items;
      s.target_begin = static_cast<int>(block_start(n_targets, t, threads));
      s.target_end = static_cast<int>(block_start(n_targets, t + 1, threads));
    }
    for (Eigen::Index item = 0; item < n_items; ++item)
      for (int target : targets_of(item))
        for (auto& s : spans_)
          if (s.owns(target)) {
            s.item_begin = std::min(s.item_begin, item);
            s.item_end = std::max(s.item_end, item + 1);
          }
    for (auto& s : spans_) s.item_begin = std::min(s.item_begin, s.item_end);
    return spans_;
  }

 private:
  int threads_ = 0, n_targets_ = -1;
  Eigen::Index n_items_ = -1;
  std::vector<OwnedSpan> spans_;
};

// Runs body(t, span) for every thread's span, on `threads` threads (inline for one).
template <class Body>
void for_owned_spans(int threads, const std::vector<OwnedSpan>& spans, Body&& body) {
  if (threads <= 1) {
    body(0, spans[0]);
    return;
  }
  run_on_threads(threads, [&](int t, int count) {
    for (int b = t; b < threads; b += count) body(b, spans[static_cast<std::size_t>(b)]);
  });
}

}  // namespace cellsim
