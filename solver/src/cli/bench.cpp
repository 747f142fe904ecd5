#include "cli/bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numeric>

#include "engine/scheme.hpp"
#include "engine/simulation.hpp"
#include "geometry/tissue.hpp"

namespace cellsim {

std::size_t BenchResult::median_repeat() const {
  std::vector<std::size_t> order(ms_per_step.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ms_per_step[a] < ms_per_step[b]; });
  return order[order.size() / 2];
}

BenchResult measure_steps(const Params& case_params, long steps, int repeats, int threads, long reference_particles) {
  const Params& p = case_params;
  const Tissue cell = build_tissue(p);
  BenchResult r;
  r.fluid_particles = cell.fluid_x.cols();
  r.wall_particles = cell.wall_x.cols();
  if (reference_particles > 0)
    steps = std::max(100L, steps * reference_particles / (r.fluid_particles + r.wall_particles));
  r.steps = steps;
  r.dt_ns = p.dt_s * 1e9;
  r.threads = threads;
  r.bonds = cell.mesh.bonds.size();
  r.hinges = cell.mesh.hinges.size();
  r.quasi_static = p.time_scheme == kQuasiStatic;
  for (int repeat = 0; repeat < repeats; ++repeat) {
    Simulation sim(p, cell);
    sim.set_threads(threads);
    const std::unique_ptr<Scheme> scheme = make_scheme(sim);  // the case's time.scheme
    sim.timer().reset();
    double evaluations = 0;
    const auto start = std::chrono::steady_clock::now();
    for (long n = 1; n <= steps; ++n) {
      scheme->step();
      evaluations += sim.state().relaxation_evaluations;  // NaN for a leapfrog step
      if (n % p.record_every == 0) {  // what a run adds at each record (snapshots are file output)
        sim.timer().start();
        sim.check_containment();
        sim.record();
        sim.timer().lap(Phase::Recording);
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.ms_per_step.push_back(1e3 * seconds / static_cast<double>(steps));
    auto& phases = r.phase_ms.emplace_back();
    for (int ph = 0; ph < static_cast<int>(Phase::Count); ++ph)
      phases[static_cast<std::size_t>(ph)] = 1e3 * sim.timer().seconds(static_cast<Phase>(ph)) / static_cast<double>(steps);
    r.evaluations_per_step = evaluations / static_cast<double>(steps);  // every repeat steps alike
    r.fluid_pairs = sim.neighbours().fluid_fluid().pairs;  // for ns-per-pair estimates
    r.wall_pairs = sim.neighbours().fluid_wall().pairs;
  }
  return r;
}

void print_benchmark(const BenchResult& r) {
  std::printf(
      "cellsim bench: %ld fluid + %ld wall particles, %ld steps x %zu repeats (drying from the start), %d thread%s\n",
      r.fluid_particles, r.wall_particles, r.steps, r.ms_per_step.size(), r.threads, r.threads == 1 ? "" : "s");
  std::printf("pair lists (cut-off + skin) at the end: %zu fluid-fluid, %zu fluid-wall; %zu bonds, %zu hinges\n",
              r.fluid_pairs, r.wall_pairs, r.bonds, r.hinges);
  if (r.quasi_static)
    std::printf("scheme: quasi-static, %.1f force evaluations a step (each relaxed to equilibrium)\n",
                r.evaluations_per_step);
  else
    std::printf("scheme: leapfrog (kick-drift-kick)\n");
  const double m = r.median_ms();
  std::printf("median %.4f ms/step (min %.4f, max %.4f), %.4f million particle-steps/s\n", m,
              *std::min_element(r.ms_per_step.begin(), r.ms_per_step.end()),
              *std::max_element(r.ms_per_step.begin(), r.ms_per_step.end()), r.million_particle_steps_per_s());
  std::printf("%-46s %10s %7s\n", "phase (of the median repeat)", "ms/step", "share");
  const auto& phases = r.phase_ms[r.median_repeat()];
  for (int ph = 0; ph < static_cast<int>(Phase::Count); ++ph)
    std::printf("%-46s %10.4f %6.1f%%\n", kPhaseNames[ph], phases[static_cast<std::size_t>(ph)],
                100.0 * phases[static_cast<std::size_t>(ph)] / m);
}

std::vector<BenchSize> bench_sizes(const Params& p) {
  std::vector<BenchSize> sizes;
  for (int level : {1, 2, 3}) {
    const double fluid_factor = std::pow(2.0, 1.5 * (level - 1)), wall_factor = std::pow(2.0, level - 1);
    char dt[64];
    std::snprintf(dt, sizeof dt, "%.17g", p.dt_s * 1e9 * (level >= 3 ? 0.5 : 1.0));
    sizes.push_back({"L" + std::to_string(level),
                     {"cell.n_fluid=" + std::to_string(std::lround(static_cast<double>(p.n_fluid) * fluid_factor)),
                      "cell.n_wall=" + std::to_string(std::lround(static_cast<double>(p.n_wall) * wall_factor)),
                      std::string("time.dt_ns=") + dt}});
  }
  // Plates one cell wider than the tissue, as the tissue study's (they act only in compression).
  for (int k : {2, 3}) {
    const std::string n = std::to_string(k), plate_um = std::to_string(std::lround((k + 1) * p.diameter_m * 1e6));
    sizes.push_back({n + "x" + n + "x" + n,
                     {"tissue.cells_x=" + n, "tissue.cells_y=" + n, "tissue.cells_z=" + n,
                      "compression.plate_length_um=" + plate_um, "compression.plate_width_um=" + plate_um}});
  }
  return sizes;
}

void print_size_table(const std::vector<std::string>& labels, const std::vector<BenchResult>& results) {
  std::printf("%5s %7s %6s %7s %7s %6s %26s %9s %12s %8s\n", "size", "fluid", "wall", "dt_ns", "threads", "steps",
              "ms/step median (range)", "M p-st/s", "ns/p-step", "speed-up");
  double one_thread_ms = 0;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const BenchResult& r = results[i];
    if (r.threads == 1) one_thread_ms = r.median_ms();
    char range[64];
    std::snprintf(range, sizeof range, "%.4f (%.4f-%.4f)", r.median_ms(),
                  *std::min_element(r.ms_per_step.begin(), r.ms_per_step.end()),
                  *std::max_element(r.ms_per_step.begin(), r.ms_per_step.end()));
    std::printf("%5s %7ld %6ld %7.3g %7d %6ld %26s %9.2f %12.1f %8.2f\n", labels[i].c_str(), r.fluid_particles,
                r.wall_particles, r.dt_ns, r.threads, r.steps, range, r.million_particle_steps_per_s(),
                1e3 / r.million_particle_steps_per_s(), one_thread_ms / r.median_ms());
  }
  std::printf("\nphase, ms/step of the median repeat (size, T threads):\n%-28s", "");
  for (std::size_t i = 0; i < results.size(); ++i) std::printf(" %7s T%d", labels[i].c_str(), results[i].threads);
  std::printf("\n");
  for (int ph = 0; ph < static_cast<int>(Phase::Count); ++ph) {
    std::string name = kPhaseNames[ph];
    name = name.substr(0, name.find(" ("));
    std::printf("%-28s", name.c_str());
    for (const BenchResult& r : results) std::printf(" %10.4f", r.phase_ms[r.median_repeat()][static_cast<std::size_t>(ph)]);
    std::printf("\n");
  }
}

}  // namespace cellsim
