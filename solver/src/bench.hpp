#pragma once
// `cellsim bench`: the speed of the step on a case, as the median of repeats, with the time per phase.
#include "params.hpp"

namespace cellsim {

struct BenchOptions {
  long steps = 2000;
  int repeats = 5;
  int threads = 1;
};

void run_benchmark(Params p, const BenchOptions& options);

}  // namespace cellsim
