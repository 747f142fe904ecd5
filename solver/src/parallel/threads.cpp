#include "parallel/threads.hpp"

namespace cellsim {

void run_on_threads(int threads, const std::function<void(int t, int count)>& body) {
  // Threads bound to cores (spread): unbound, the scheduler often stacked them on one core.
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) proc_bind(spread)
  body(thread_index(), team_size());
#else
  (void)threads;
  body(0, 1);
#endif
}

void wait_for_all_threads() {
#ifdef _OPENMP
#pragma omp barrier
#endif
}

}  // namespace cellsim
