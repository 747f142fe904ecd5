#pragma once
// Threads for one run (`cellsim run --threads N`): the fluid pair loop, half of a step, is shared
// among them. The default is 1, so that a workflow runs one job per core. Results are bit-identical
// for the same input and thread count; between thread counts they agree to round-off (the pair
// sums are added in another order). Without OpenMP (CELLSIM_OPENMP=OFF) only 1 thread is possible.
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "errors.hpp"

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

inline void check_thread_count(long threads) {
  if (threads < 1 || threads > kMaxThreads)
    throw InputError("--threads = " + std::to_string(threads) + ": must be between 1 and " +
                     std::to_string(kMaxThreads));
  if (threads > 1 && !built_with_openmp())
    throw InputError("--threads = " + std::to_string(threads) +
                     ": this cellsim was built without OpenMP (CELLSIM_OPENMP=OFF), so only 1 thread");
}

}  // namespace cellsim
