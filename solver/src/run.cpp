#include "run.hpp"

#include <vector>

#include "case_file.hpp"
#include "cell.hpp"
#include "errors.hpp"
#include "progress.hpp"
#include "result_file.hpp"
#include "simulation.hpp"

namespace cellsim {
namespace {

// Steps, records and snapshots for one stage. A record and a snapshot are taken at the stage's
// last step whatever the intervals, so every stage's end state is in the file.
void run_stage(Simulation& sim, std::int64_t steps, ResultFile& out, std::vector<Record>& records,
               Progress& progress, const char* name) {
  const Params& p = sim.params();
  for (std::int64_t n = 1; n <= steps; ++n) {
    sim.step();
    const bool last = n == steps;
    if (n % p.record_every == 0 || last) {
      sim.check_containment();
      records.push_back(sim.record());
    }
    if ((p.snapshot_every > 0 && n % p.snapshot_every == 0) || last) out.write_snapshot(sim.state(), sim.eos());
    progress.update(sim.state().step, sim.state().time_s, name);
  }
}

}  // namespace

void run_case(Params p, const RunOptions& options) {
  const Cell cell = build_cell(p);  // fills in derived parameters
  ResultFile out(options.output_path);
  out.write_header(case_to_json(p));
  out.write_mesh(cell.mesh, static_cast<long>(p.n_fluid));

  Simulation sim(p, cell);
  std::vector<Record> records{sim.record()};
  out.write_snapshot(sim.state(), sim.eos());
  Progress progress(p.drying_steps + p.compression_steps, p.progress_interval_s, options.quiet);
  try {
    run_stage(sim, p.drying_steps, out, records, progress, "drying");
    if (p.compression_steps > 0) {
      sim.start_compression();
      run_stage(sim, p.compression_steps, out, records, progress, "compression");
    }
  } catch (const NumericalFailure& e) {
    out.fail(records, e.what());
    throw NumericalFailure(std::string(e.what()) + "; partial results in " + out.partial_path());
  }
  progress.finish(sim.state().step, sim.state().time_s);
  out.complete(records, sim.state());
}

}  // namespace cellsim
