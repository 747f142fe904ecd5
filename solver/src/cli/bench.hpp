#pragma once
// `cellsim bench`: the speed of the step on a case, as the median of repeats, with the time per
// phase; with --sizes, the same case at the convergence study's three resolution levels and as tissues
// of 8 and 27 cells, on one thread and on several.
#include <array>
#include <string>
#include <vector>

#include "core/params.hpp"
#include "engine/phase_timer.hpp"

namespace cellsim {

struct BenchOptions {
  long steps = 2000;
  int repeats = 5;
  int threads = 1;
};

struct BenchResult {
  long fluid_particles = 0, wall_particles = 0, steps = 0;
  double dt_ns = 0;
  int threads = 1;
  std::vector<double> ms_per_step;                                        // per repeat
  std::vector<std::array<double, static_cast<int>(Phase::Count)>> phase_ms;  // per repeat, per step
  std::size_t fluid_pairs = 0, wall_pairs = 0, bonds = 0, hinges = 0;
  // The case's time.scheme, and for the quasi-static one its relaxation's force evaluations a step (the
  // mean over a repeat's steps, which every repeat steps alike; NaN for the leapfrog).
  bool quasi_static = false;
  double evaluations_per_step = 0;

  // The repeat with the median time; its phases add up to its time (the medians of the phases of
  // different repeats need not).
  std::size_t median_repeat() const;
  double median_ms() const { return ms_per_step[median_repeat()]; }
  double million_particle_steps_per_s() const {
    return static_cast<double>(fluid_particles + wall_particles) / median_ms() * 1e-3;
  }
};

// `steps` steps of the case, `repeats` times; with reference_particles > 0, as many fewer steps as it
// has more particles than that (at least 100), so that every size of `--sizes` takes about as long.
BenchResult measure_steps(const Params& p, long steps, int repeats, int threads, long reference_particles = 0);
void print_benchmark(const BenchResult& r);

// The sizes of `bench --sizes`: the case at the convergence study's resolution levels (config/config.yaml,
// axis `resolution`: level L has 2^(3(L-1)/2) times the fluid particles and 2^(L-1) times the wall
// particles of the case, and level 3 halves the time step), then tissues of 2 x 2 x 2 and 3 x 3 x 3 of
// its cell (the tissue study's sizes, axis `cells`), each with the overrides (for --set) that make it.
struct BenchSize {
  std::string label;  // "L1", "L2", "L3", "2x2x2", "3x3x3"
  std::vector<std::string> overrides;
};
std::vector<BenchSize> bench_sizes(const Params& p);

// One row per (size, thread count), then the phases side by side.
void print_size_table(const std::vector<std::string>& labels, const std::vector<BenchResult>& results);

}  // namespace cellsim
