#include "bench.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "cell.hpp"
#include "simulation.hpp"

namespace cellsim {

void run_benchmark(Params p, const BenchOptions& options) {
  const Cell cell = build_cell(p);
  const long n_particles = cell.fluid_x.cols() + cell.wall_x.cols();
  std::printf(
      "cellsim bench: %ld fluid + %ld wall particles, %ld steps x %d repeats (drying from the start), %d thread%s\n",
      static_cast<long>(cell.fluid_x.cols()), static_cast<long>(cell.wall_x.cols()), options.steps, options.repeats,
      options.threads, options.threads == 1 ? "" : "s");
  std::vector<double> ms_per_step;
  std::vector<std::vector<double>> phase_ms(static_cast<int>(Phase::Count));
  std::size_t fluid_pairs = 0, wall_pairs = 0;
  for (int r = 0; r < options.repeats; ++r) {
    Simulation sim(p, cell);
    sim.set_threads(options.threads);
    sim.timer().reset();
    const auto start = std::chrono::steady_clock::now();
    for (long n = 1; n <= options.steps; ++n) {
      sim.step();
      if (n % p.record_every == 0) {  // what a run adds at each record (snapshots are file output)
        sim.timer().start();
        sim.check_containment();
        sim.record();
        sim.timer().lap(Phase::Recording);
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ms_per_step.push_back(1e3 * seconds / options.steps);
    for (int ph = 0; ph < static_cast<int>(Phase::Count); ++ph)
      phase_ms[ph].push_back(1e3 * sim.timer().seconds(static_cast<Phase>(ph)) / options.steps);
    fluid_pairs = sim.neighbours().fluid_fluid().pairs;  // for ns-per-pair estimates
    wall_pairs = sim.neighbours().fluid_wall().pairs;
  }
  std::printf("pair lists (cut-off + skin) at the end: %zu fluid-fluid, %zu fluid-wall; %zu bonds, %zu hinges\n",
              fluid_pairs, wall_pairs, cell.mesh.bonds.size(), cell.mesh.hinges.size());
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  const double m = median(ms_per_step);
  std::printf("median %.4f ms/step (min %.4f, max %.4f), %.2f million particle-steps/s\n", m,
              *std::min_element(ms_per_step.begin(), ms_per_step.end()),
              *std::max_element(ms_per_step.begin(), ms_per_step.end()), n_particles / m * 1e-3);
  std::printf("%-46s %10s %7s\n", "phase", "ms/step", "share");
  for (int ph = 0; ph < static_cast<int>(Phase::Count); ++ph) {
    const double t = median(phase_ms[ph]);
    std::printf("%-46s %10.4f %6.1f%%\n", kPhaseNames[ph], t, 100.0 * t / m);
  }
}

}  // namespace cellsim
