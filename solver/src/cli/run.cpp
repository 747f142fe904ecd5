#include "cli/run.hpp"

#include <cstdio>
#include <functional>
#include <vector>

#include "cli/progress.hpp"
#include "core/errors.hpp"
#include "engine/settle.hpp"
#include "engine/simulation.hpp"
#include "engine/steady_state.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"
#include "io/result_file.hpp"
#include "io/state_io.hpp"

namespace cellsim {
namespace {

// Steps, records and snapshots for one stage, until `steps` or until done() says stop. done() is
// asked after every step, with the record taken at that step (nullptr if none). A record and a
// snapshot are taken at the stage's last step whatever the intervals.
void run_stage(Simulation& sim, std::int64_t steps, const std::function<bool(const Record*)>& done,
               ResultFile& out, std::vector<Record>& records, Progress& progress, const char* name) {
  const Params& p = sim.params();
  const auto take_record = [&] {
    sim.check_containment();
    records.push_back(sim.record());
    return &records.back();
  };
  for (std::int64_t n = 1; n <= steps; ++n) {
    sim.step();
    const Record* recorded = n % p.record_every == 0 ? take_record() : nullptr;
    const bool last = n == steps || done(recorded);
    if (last && !recorded) take_record();
    if ((p.snapshot_every > 0 && n % p.snapshot_every == 0) || last) out.write_snapshot(sim.state(), sim.eos());
    progress.step(sim.state().time_s, name);
    if (last) {
      progress.unplan(steps - n);
      break;
    }
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
  const Tissue tissue = build_tissue(p);  // fills in derived parameters
  const nlohmann::json resolved = case_to_json(p);
  SavedRun dried;
  if (!options.from_path.empty()) {
    dried = read_saved_run(options.from_path);
    check_same_drying(nlohmann::json::parse(dried.case_json), resolved, options.from_path);
    if (dried.state.stage != Stage::Drying)
      throw InputError("--from '" + options.from_path + "' holds a state in compression, not the end of drying "
                       "(run the case with compression.steps = 0)");
  }
  Simulation sim(p, tissue);  // refuses a time step over the wall-spring limit, before any output
  sim.set_threads(options.threads);
  ResultFile out(options.output_path);
  out.write_header(resolved, options.threads);
  out.write_mesh(tissue.mesh, tissue.cells, tissue.lamella);

  std::vector<Record> records;
  DryingSummary drying;
  const std::int64_t drying_steps = options.from_path.empty() ? p.drying_steps : 0;
  const auto strain_reached = [&](const Record*) { return p.end_strain && sim.nominal_strain() >= *p.end_strain; };
  const SteadyStateCriterion steady = steady_state_criterion(p);
  const auto steady_reached = [&](const Record* recorded) {
    if (!recorded || !is_steady(records, steady)) return false;
    drying.steady = true;
    drying.steady_time_s = recorded->time_s;
    return true;
  };
  try {
    if (options.from_path.empty()) {
      drying.settle = settle(sim, p.settle_max_iterations, p.settle_tolerance);  // t = 0: the cell at rest
      if (!options.quiet)
        std::fprintf(stderr, "cellsim: settle: %lld pseudo-steps to rest at %.1f kPa, residual %.2g, fluid mass x %.4f\n",
                     static_cast<long long>(drying.settle.iterations), p.turgor_Pa / 1e3, drying.settle.residual,
                     drying.settle.mass_ratio);
      records.push_back(sim.record());
    } else {
      sim.restore(dried.state);
      records = std::move(dried.records);
      drying = dried.drying;
    }
    out.write_snapshot(sim.state(), sim.eos());
    Progress progress(drying_steps + p.compression_steps, p.progress_interval_s, options.quiet);
    if (drying_steps > 0) {
      run_stage(sim, drying_steps, steady_reached, out, records, progress, "drying");
      if (drying.steady && !options.quiet)
        std::fprintf(stderr, "cellsim: drying reached steady state at t = %.2f us (step %lld)\n",
                     drying.steady_time_s * 1e6, static_cast<long long>(sim.state().step));
    }
    if (!drying.warning().empty()) std::fprintf(stderr, "cellsim: WARNING: %s\n", drying.warning().c_str());
    if (p.compression_steps > 0) {
      sim.start_compression();
      run_stage(sim, p.compression_steps, strain_reached, out, records, progress, "compression");
    }
    progress.finish(sim.state().time_s);
  } catch (const NumericalFailure& e) {
    out.write_drying_summary(drying);
    out.write_snapshot(sim.state(), sim.eos());  // the failing state, for diagnosis
    out.fail(records, e.what());
    throw NumericalFailure(std::string(e.what()) + "; partial results in " + out.partial_path());
  }
  out.write_drying_summary(drying);
  out.complete(records, sim.state());
}

}  // namespace cellsim
