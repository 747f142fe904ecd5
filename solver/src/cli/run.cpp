#include "cli/run.hpp"

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <sstream>
#include <vector>

#include "cli/progress.hpp"
#include "core/errors.hpp"
#include "engine/scheme.hpp"
#include "engine/settle.hpp"
#include "engine/simulation.hpp"
#include "engine/steady_state.hpp"
#include "engine/volumetric_modulus.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"
#include "io/result_file.hpp"
#include "io/state_io.hpp"

namespace cellsim {
namespace {

// Steps, records and snapshots for one stage, until `steps` or until done() says stop. done() is
// asked after every step, with the record taken at that step (nullptr if none). A record and a
// snapshot are taken at the stage's last step whatever the intervals.
void run_stage(Simulation& sim, const std::function<void()>& step, std::int64_t steps,
               const std::function<bool(const Record*)>& done,
               ResultFile& out, std::vector<Record>& records, Progress& progress, const char* name,
               const std::function<double()>& reached = [] { return 0.0; }) {
  const Params& p = sim.params();
  const auto take_record = [&] {
    sim.check_containment();
    records.push_back(sim.record());
    return &records.back();
  };
  for (std::int64_t n = 1; n <= steps; ++n) {
    step();
    const Record* recorded = n % p.record_every == 0 ? take_record() : nullptr;
    const bool last = n == steps || done(recorded);
    if (last && !recorded) take_record();
    if ((p.snapshot_every > 0 && n % p.snapshot_every == 0) || last) out.write_snapshot(sim.state(), sim.eos());
    progress.step(sim.state().time_s, name, reached());
    if (last) {
      progress.unplan(steps - n);
      break;
    }
  }
}

// The keys a saved state may differ in from this case: compression and output act only after the
// end of drying; the relaxation's iteration cap only stops a run, it never shapes a state. A state at
// rest (a run with drying.steps = 0) may also differ in the dryness and the length of drying: at t = 0
// the drying ramp is 0 (drying.hpp), so the settle does not see them.
bool may_differ(const std::string& section, const std::string& key, bool at_rest) {
  if (section == "compression" || section == "output") return true;
  if (section == "time" && key == "relaxation_max_iterations") return true;
  return at_rest && section == "drying" && (key == "dryness" || key == "steps");
}

// A saved state may seed this case only if everything that shaped it is the same.
void check_same_start(const nlohmann::json& saved, const nlohmann::json& now, const std::string& from, bool at_rest) {
  for (const auto& [section, keys] : now.items()) {
    for (const auto& [key, value] : keys.items()) {
      if (may_differ(section, key, at_rest)) continue;
      const nlohmann::json& old = saved.contains(section) && saved[section].contains(key) ? saved[section][key]
                                                                                          : nlohmann::json();
      if (old != value)
        throw InputError("--from '" + from + "' was " + (at_rest ? "settled" : "dried") + " with " + section + "." +
                         key + " = " + old.dump() + ", but this case has " + value.dump() +
                         "; run it again or match the case");
    }
  }
}

// The end a compression was asked for, as its key says it ("" if none: it runs its steps).
std::string asked_end(const Params& p) {
  std::ostringstream end;
  if (p.unload_at_strain)
    end << "the cell left the top plate after compression.unload_at_strain = " << *p.unload_at_strain;
  else if (p.end_strain)
    end << "compression.end_strain = " << *p.end_strain;
  return end.str();
}

}  // namespace

void run_case(const Params& p, const RunOptions& options) {
  const Tissue tissue = build_tissue(p);
  const nlohmann::json resolved = case_to_json(p);
  // --from: a state at rest (step 0: settled, not dried) starts drying; the end of drying, compression.
  SavedRun saved;
  bool from_rest = false;
  if (!options.from_path.empty()) {
    saved = read_saved_run(options.from_path);
    if (saved.state.stage != Stage::Drying)
      throw InputError("--from '" + options.from_path + "' holds a state in compression, not the end of drying "
                       "(run the case with compression.steps = 0)");
    from_rest = saved.state.step == 0;
    check_same_start(saved.case_doc, resolved, options.from_path, from_rest);
    if (saved.threads != options.threads)
      std::fprintf(stderr,
                   "cellsim: note: --from '%s' ran on %d thread(s) and this run on %d: the result agrees with one "
                   "run to round-off, not bit for bit (give both the same --threads for that)\n",
                   options.from_path.c_str(), saved.threads, options.threads);
  }
  Simulation sim(p, tissue);  // refuses a time step over the wall-spring limit, before any output
  sim.set_threads(options.threads);
  // time.scheme: a leapfrog step, or a step of loads and a relaxation to equilibrium (scheme.hpp).
  const std::unique_ptr<Scheme> scheme = make_scheme(sim);
  const std::function<void()> step = [&] { scheme->step(); };
  if (!options.from_path.empty()) {  // a saved state that does not fit this case: refused before any output
    try {
      check_restorable(saved.state, sim.state(), sim.mesh().bonds.size());
    } catch (const InputError& e) {
      throw InputError("--from '" + options.from_path + "': " + e.what());
    }
  }
  ResultFile out(options.output_path);
  out.write_header(resolved, options.threads);
  out.write_mesh(tissue.mesh, tissue.cells, tissue.lamella);

  std::vector<Record> records;
  DryingSummary drying;
  CompressionSummary compression;
  const std::int64_t drying_steps = options.from_path.empty() || from_rest ? *p.drying_steps : 0;
  // Compression ends at compression.end_strain, or, unloading, when the cell leaves the top plate.
  const auto strain_reached = [&](const Record*) {
    const Plates& plates = sim.state().plates;
    if (plates.unloading) return plates.force_top_N <= 0;
    return p.end_strain && sim.nominal_strain() >= *p.end_strain;
  };
  const SteadyStateCriterion steady = steady_state_criterion(p);
  const auto steady_reached = [&](const Record* recorded) {
    if (!recorded || !is_steady(records, steady)) return false;
    drying.steady = true;
    drying.steady_time_s = recorded->time_s;
    return true;
  };
  try {
    if (options.from_path.empty()) {
      const auto settle_start = std::chrono::steady_clock::now();
      drying.settle = settle(sim, p.settle_max_iterations, p.settle_tolerance);  // t = 0: the cell at rest
      const double settle_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - settle_start).count();
      if (!options.quiet)  // the run's "done" line times the steps only, so the settle says its own time
        std::fprintf(stderr,
                     "cellsim: settle: %lld pseudo-steps to rest at %.1f kPa, residual %.2g, fluid mass x %.4f, "
                     "%.1f s wall time\n",
                     static_cast<long long>(drying.settle.iterations), p.turgor_Pa / 1e3, drying.settle.residual,
                     drying.settle.mass_ratio, settle_s);
      records.push_back(sim.record());
    } else if (from_rest) {
      // The settled state, rates and record as the settle above would leave them (restore() builds
      // the lists and rates anew, as settle's start_at_rest() does): the same bits.
      sim.restore(saved.state);
      drying.settle = saved.drying.settle;
      records.push_back(sim.record());
      if (!options.quiet)
        std::fprintf(stderr, "cellsim: settle: the state at rest from %s (%lld pseudo-steps, residual %.2g)\n",
                     options.from_path.c_str(), static_cast<long long>(drying.settle.iterations),
                     drying.settle.residual);
    } else {
      sim.restore(saved.state);
      records = std::move(saved.records);
      drying = saved.drying;
    }
    out.write_snapshot(sim.state(), sim.eos());
    const std::int64_t compression_steps = *p.compression_steps;
    Progress progress(drying_steps + compression_steps, p.progress_interval_s, options.quiet);
    if (drying_steps > 0) {
      run_stage(sim, step, drying_steps, steady_reached, out, records, progress, "drying");
      if (drying.steady && !options.quiet)
        std::fprintf(stderr, "cellsim: drying reached steady state at t = %.2f us (step %lld)\n",
                     drying.steady_time_s * 1e6, static_cast<long long>(sim.state().step));
    }
    drying.dried = drying_steps > 0 || (!options.from_path.empty() && !from_rest);
    if (drying_steps > 0 || options.from_path.empty()) {  // else carried from the saved run
      drying.volumetric_modulus_Pa = volumetric_modulus_Pa(sim);
      if (drying_steps > 0)
        drying.energy_residual_share = residual_over_flows(records.back().energy, records.back().energy_residual_J);
    }
    if (!drying.warning().empty()) std::fprintf(stderr, "cellsim: WARNING: %s\n", drying.warning().c_str());
    if (compression_steps > 0) {
      const Record dried = records.back();
      scheme->start_compression();
      if (p.end_strain && !p.unload_at_strain) progress.aim("strain", *p.end_strain);
      run_stage(sim, step, compression_steps, strain_reached, out, records, progress, "compression",
                [&] { return sim.nominal_strain(); });
      const double work_J = records.back().energy[kPlateWork] - dried.energy[kPlateWork];
      compression = {true, asked_end(p), strain_reached(nullptr), compression_steps, sim.nominal_strain(),
                     work_J != 0 ? (records.back().energy_residual_J - dried.energy_residual_J) / work_J : std::nan("")};
      if (!compression.warning().empty())
        std::fprintf(stderr, "cellsim: WARNING: %s\n", compression.warning().c_str());
    }
    progress.finish(sim.state().time_s);
  } catch (const NumericalFailure& e) {
    out.write_run_summary(drying, compression);
    out.write_snapshot(sim.state(), sim.eos());  // the failing state, for diagnosis
    out.fail(records, e.what());
    throw NumericalFailure(std::string(e.what()) + "; partial results in " + out.partial_path());
  }
  out.write_run_summary(drying, compression);
  out.complete(records, sim.state());
}

}  // namespace cellsim
