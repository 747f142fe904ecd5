#include "run.hpp"

#include <functional>
#include <vector>

#include "case_file.hpp"
#include "cell.hpp"
#include "errors.hpp"
#include "progress.hpp"
#include "result_file.hpp"
#include "simulation.hpp"
#include "state_io.hpp"

namespace cellsim {
namespace {

// Steps, records and snapshots for one stage, until `steps` or until done() says stop. A record
// and a snapshot are taken at the stage's last step whatever the intervals.
void run_stage(Simulation& sim, std::int64_t steps, const std::function<bool()>& done, ResultFile& out,
               std::vector<Record>& records, Progress& progress, const char* name) {
  const Params& p = sim.params();
  for (std::int64_t n = 1; n <= steps; ++n) {
    sim.step();
    const bool last = n == steps || done();
    if (n % p.record_every == 0 || last) {
      sim.check_containment();
      records.push_back(sim.record());
    }
    if ((p.snapshot_every > 0 && n % p.snapshot_every == 0) || last) out.write_snapshot(sim.state(), sim.eos());
    progress.update(sim.state().step, sim.state().time_s, name);
    if (last) break;
  }
}

// A saved state may seed this case only if everything that shapes drying is the same.
void check_same_drying(const nlohmann::json& saved, const nlohmann::json& now, const std::string& from) {
  for (const auto& [section, keys] : now.items()) {
    if (section == "compression" || section == "output") continue;
    for (const auto& [key, value] : keys.items()) {
      const nlohmann::json& old = saved.contains(section) && saved[section].contains(key) ? saved[section][key]
                                                                                          : nlohmann::json();
      if (old != value)
        throw InputError("--from '" + from + "' was dried with " + section + "." + key + " = " + old.dump() +
                         ", but this case has " + value.dump() + "; dry again or match the case");
    }
  }
}

}  // namespace

void run_case(Params p, const RunOptions& options) {
  const Cell cell = build_cell(p);  // fills in derived parameters
  const nlohmann::json resolved = case_to_json(p);
  SavedRun dried;
  if (!options.from_path.empty()) {
    dried = read_saved_run(options.from_path);
    check_same_drying(nlohmann::json::parse(dried.case_json), resolved, options.from_path);
    if (dried.state.stage != Stage::Drying || dried.state.step != p.drying_steps)
      throw InputError("--from '" + options.from_path + "' holds the state after step " +
                       std::to_string(dried.state.step) + " of " +
                       (dried.state.stage == Stage::Drying ? "drying" : "compression") +
                       ", not the end of drying (run it with compression.steps = 0)");
  }
  Simulation sim(p, cell);  // refuses a time step over the wall-spring limit, before any output
  sim.set_threads(options.threads);
  ResultFile out(options.output_path);
  out.write_header(resolved, options.threads);
  out.write_mesh(cell.mesh, static_cast<long>(p.n_fluid));

  std::vector<Record> records;
  if (options.from_path.empty()) {
    records.push_back(sim.record());
  } else {
    sim.restore(dried.state);
    records = std::move(dried.records);
  }
  out.write_snapshot(sim.state(), sim.eos());
  const std::int64_t drying_steps = options.from_path.empty() ? p.drying_steps : 0;
  Progress progress(drying_steps + p.compression_steps, p.progress_interval_s, options.quiet);
  const auto strain_reached = [&] { return p.end_strain && sim.nominal_strain() >= *p.end_strain; };
  try {
    run_stage(sim, drying_steps, [] { return false; }, out, records, progress, "drying");
    if (p.compression_steps > 0) {
      sim.start_compression();
      run_stage(sim, p.compression_steps, strain_reached, out, records, progress, "compression");
    }
  } catch (const NumericalFailure& e) {
    out.write_snapshot(sim.state(), sim.eos());  // the failing state, for diagnosis
    out.fail(records, e.what());
    throw NumericalFailure(std::string(e.what()) + "; partial results in " + out.partial_path());
  }
  progress.finish(sim.state().step, sim.state().time_s);
  out.complete(records, sim.state());
}

}  // namespace cellsim
