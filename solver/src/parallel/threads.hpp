#pragma once
// Threads for one run (`cellsim run --threads N`): every phase of the step is shared among them
// (docs/performance.md gives the rules). The default is 1, so that a workflow runs one job per core.
// Results are bit-identical for the same input and thread count; between thread counts they agree to
// round-off (sums over particles are added in blocks of another size). Without OpenMP
// (CELLSIM_OPENMP=OFF) only 1 thread is possible.
#include <array>
#include <functional>
#include <string>

#include <Eigen/Core>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/errors.hpp"

namespace cellsim {

inline constexpr int kMaxThreads = 256;

inline bool built_with_openmp() {
#ifdef _OPENMP
  return true;
#else
  return false;
#endif
}

// The index of the calling thread within the current parallel region (0 outside one), and the
// number of threads the region really got (the runtime may give fewer than asked, e.g. under
// OMP_THREAD_LIMIT).
inline int thread_index() {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}
inline int team_size() {
#ifdef _OPENMP
  return omp_get_num_threads();
#else
  return 1;
#endif
}

// Within its scope no parallel region gets more than one thread: for a library whose own OpenMP loops ask
// for a fixed team whatever `--threads` says (CHOLMOD's: 4), so that a workflow's job keeps to its core.
class SerialOpenMP {
 public:
#ifdef _OPENMP
  SerialOpenMP() : levels_(omp_get_max_active_levels()) { omp_set_max_active_levels(0); }
  ~SerialOpenMP() { omp_set_max_active_levels(levels_); }
#else
  SerialOpenMP() {}  // nothing to hold without OpenMP (user-provided: no unused-variable warning)
#endif
  SerialOpenMP(const SerialOpenMP&) = delete;
  SerialOpenMP& operator=(const SerialOpenMP&) = delete;

 private:
#ifdef _OPENMP
  int levels_;
#endif
};

// The first of n items in block b of `blocks`: block b is [block_start(n, b), block_start(n, b + 1)).
// Every loop of a step cuts its particles with this one rule, so a thread works on the same
// particles in each (docs/performance.md, rule 1).
inline Eigen::Index block_start(Eigen::Index n, int b, int blocks) { return n * b / blocks; }

// Runs body(t, count) on `threads` threads at once, t = 0 .. count - 1 (count: the threads the
// runtime gave). Defined apart from the loops that use it: a parallel region in a function slows
// that function's one-thread path (the compiler moves its locals into a shared frame).
void run_on_threads(int threads, const std::function<void(int t, int count)>& body);
void wait_for_all_threads();  // a barrier, for a body of run_on_threads

// Calls work(begin, end) on contiguous blocks that cover [0, n), one block per thread. For loops
// whose every element is computed on its own (no sums across elements), so the result is the same
// for every thread count. threads == 1 runs inline.
template <class Work>
void for_blocks(int threads, Eigen::Index n, Work&& work) {
  if (threads <= 1 || n < 2 * threads) {
    work(Eigen::Index{0}, n);
    return;
  }
  run_on_threads(threads, [&](int t, int count) { work(block_start(n, t, count), block_start(n, t + 1, count)); });
}

// Reduces over [0, n) in `threads` fixed blocks: part(begin, end) gives each block's result, and
// combine(a, b) folds them in block order. The blocks are the same as for_blocks' when the runtime
// gives every thread asked for, so each thread reads the particles it writes elsewhere.
template <class Result, class Part, class Combine>
Result reduce_blocks(int threads, Eigen::Index n, Part&& part, Combine&& combine) {
  if (threads <= 1 || n < 2 * threads) return part(Eigen::Index{0}, n);
  std::array<Result, kMaxThreads> parts;
  run_on_threads(threads, [&](int t, int count) {
    for (int b = t; b < threads; b += count)
      parts[static_cast<std::size_t>(b)] = part(block_start(n, b, threads), block_start(n, b + 1, threads));
  });
  Result result = parts[0];
  for (int b = 1; b < threads; ++b) result = combine(result, parts[static_cast<std::size_t>(b)]);
  return result;
}

inline void check_thread_count(long threads) {
  if (threads < 1 || threads > kMaxThreads)
    throw InputError("--threads = " + std::to_string(threads) + ": must be between 1 and " +
                     std::to_string(kMaxThreads));
  if (threads > 1 && !built_with_openmp())
    throw InputError("--threads = " + std::to_string(threads) +
                     ": this cellsim was built without OpenMP (CELLSIM_OPENMP=OFF), so only 1 thread");
}

}  // namespace cellsim
