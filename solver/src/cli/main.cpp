// cellsim: one apple parenchyma cell, dried then compressed (Rathnayaka et al. 2020).
// JSON case in, HDF5 (+ XDMF) out. See README.md and docs/case-reference.md.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "cli/bench.hpp"
#include "cli/run.hpp"
#include "core/errors.hpp"
#include "engine/measures.hpp"
#include "engine/simulation.hpp"
#include "geometry/tissue.hpp"
#include "io/case_file.hpp"
#include "io/case_schema.hpp"
#include "io/energy_terms_json.hpp"
#include "io/version.hpp"
#include "parallel/threads.hpp"

namespace {

const char* kUsage =
    "usage:\n"
    "  cellsim run CASE.json -o OUT.h5 [--set key=value ...] [--from SAVED.h5] [--threads N] [--quiet]\n"
    "  cellsim validate CASE.json [--set key=value ...]   check a case, print it resolved\n"
    "  cellsim bench [CASE.json] [--steps N] [--repeats R] [--threads N] [--sizes] [--set ...]\n"
    "                                                    median ms/step, per phase; --sizes: at the three\n"
    "                                                    resolution levels and as tissues of 8 and 27 cells,\n"
    "                                                    on 1 and N (at least 2) threads\n"
    "  cellsim params                                    the case keys (Markdown table)\n"
    "  cellsim schema                                    JSON Schema of the case file\n"
    "  cellsim outputs                                   the time series written (Markdown table)\n"
    "  cellsim energy-terms                              the energy account's terms (JSON): column, role, sign\n"
    "  cellsim --help | --version\n"
    "\n"
    "--from continues from the last state in SAVED.h5, a run of the same case: the end of drying (a run\n"
    "with compression.steps = 0) is compressed; a cell at rest (drying.steps = 0 too) is dried, and\n"
    "may differ in drying.dryness and drying.steps. The output holds the whole history.\n"
    "--threads N shares every phase of the step among N threads (default 1: a workflow runs one job\n"
    "per core); results are bit-identical for the same N and agree to round-off between counts.\n"
    "Keys use units in their names, e.g. --set drying.dryness=0.5 --set wall.G_MPa=0.18.\n"
    "Exit codes: 0 success, 2 bad input (nothing written), 3 numerical failure (OUT.partial kept),\n"
    "4 file error (the file system refused: the message says what HDF5 and the system said).\n";

struct Args {
  std::string command, case_path, output_path, from_path;
  std::vector<std::string> overrides;
  bool quiet = false;
  bool sizes = false;
  bool help = false;  // --help after a command: the usage, as `cellsim --help`
  long steps = 2000;
  int repeats = 5;
  int threads = 1;
};

long positive_int(const std::string& flag, const std::string& text) {
  try {
    std::size_t used = 0;
    const long v = std::stol(text, &used);
    if (used == text.size() && v > 0) return v;
  } catch (const std::exception&) {
  }
  throw cellsim::InputError(flag + " = '" + text + "': expected a positive integer");
}

Args parse(int argc, char** argv) {
  Args a;
  std::vector<std::string> words(argv + 1, argv + argc);
  if (words.empty()) throw cellsim::InputError("no command given\n" + std::string(kUsage));
  a.command = words[0];
  for (std::size_t i = 1; i < words.size(); ++i) {
    const std::string& w = words[i];
    const auto value = [&](const std::string& flag) {
      if (i + 1 >= words.size()) throw cellsim::InputError(flag + " needs a value");
      return words[++i];
    };
    if (w == "-o" || w == "--output") a.output_path = value(w);
    else if (w == "--set") a.overrides.push_back(value(w));
    else if (w == "--from") a.from_path = value(w);
    else if (w.rfind("--set=", 0) == 0) a.overrides.push_back(w.substr(6));
    else if (w == "--quiet") a.quiet = true;
    else if (w == "--help" || w == "-h") a.help = true;
    else if (w == "--sizes") a.sizes = true;
    else if (w == "--steps") a.steps = positive_int(w, value(w));
    else if (w == "--repeats") a.repeats = static_cast<int>(positive_int(w, value(w)));
    else if (w == "--threads") {
      const long threads = positive_int(w, value(w));
      cellsim::check_thread_count(threads);
      a.threads = static_cast<int>(threads);
    }
    else if (!w.empty() && w[0] == '-') throw cellsim::InputError("unknown option '" + w + "'\n" + kUsage);
    else if (a.case_path.empty()) a.case_path = w;
    else throw cellsim::InputError("unexpected argument '" + w + "'");
  }
  return a;
}

// The case file with its --set overrides, validated. Without a file, `baseline` allows the paper's
// baseline (every key at its default) instead of an error.
cellsim::Params load(const Args& a, bool baseline = false) {
  if (a.case_path.empty() && !baseline)
    throw cellsim::InputError("'" + a.command + "' needs a case file (CASE.json)");
  nlohmann::json doc = a.case_path.empty() ? nlohmann::json::object() : cellsim::read_case_file(a.case_path);
  for (const auto& o : a.overrides) cellsim::apply_override(doc, o);
  const cellsim::Params p = cellsim::validate_case(doc);
  const std::vector<std::string> ignored = cellsim::keys_the_case_ignores(doc, p);
  if (!ignored.empty()) {
    std::string keys;
    for (const auto& key : ignored) keys += (keys.empty() ? "" : ", ") + key;
    std::cerr << "cellsim: WARNING: this case's fluid.model and time.scheme do not read " << keys
              << " (given away from the default; ignored)\n";
  }
  return p;
}

// `cellsim bench`: one case, or with --sizes the case at the three resolution levels and as tissues of
// 8 and 27 cells (steps scaled down with the size, at least 100), each on one thread and on max(2, --threads).
void bench(const Args& a) {
  const cellsim::Params p = load(a, /*baseline=*/true);
  if (!a.sizes) {
    cellsim::print_benchmark(cellsim::measure_steps(p, a.steps, a.repeats, a.threads));
    return;
  }
  std::vector<int> thread_counts{1};
  if (cellsim::built_with_openmp()) thread_counts.push_back(std::max(2, a.threads));
  std::vector<std::string> labels;
  std::vector<cellsim::BenchResult> results;
  for (const cellsim::BenchSize& size : cellsim::bench_sizes(p)) {
    Args sized = a;
    for (const auto& o : size.overrides) sized.overrides.push_back(o);
    const cellsim::Params sp = load(sized, /*baseline=*/true);
    for (int threads : thread_counts) {
      std::cerr << "cellsim bench: " << size.label << ", " << threads << " thread" << (threads == 1 ? "" : "s") << "\n";
      labels.push_back(size.label);
      results.push_back(cellsim::measure_steps(sp, a.steps, a.repeats, threads, p.n_fluid + p.n_wall));
    }
  }
  cellsim::print_size_table(labels, results);
}

int dispatch(int argc, char** argv) {
  const Args a = parse(argc, argv);
  if (a.help || a.command == "--help" || a.command == "-h" || a.command == "help") {
    std::cout << kUsage;
    return 0;
  }
  if (a.command == "--version") {
    std::cout << "cellsim " << cellsim::kVersion << " (git " << cellsim::kGitRevision << ", " << cellsim::kInstructionSet
              << ")\n";
    return 0;
  }
  if (a.command == "params") {
    std::cout << cellsim::reference_markdown();
    return 0;
  }
  if (a.command == "schema") {
    std::cout << cellsim::json_schema();
    return 0;
  }
  if (a.command == "outputs") {
    std::cout << cellsim::output_reference_markdown();
    return 0;
  }
  if (a.command == "energy-terms") {
    std::cout << cellsim::energy_terms_json();
    return 0;
  }
  if (a.command == "validate") {
    const cellsim::Params p = load(a);
    const cellsim::Tissue tissue = cellsim::build_tissue(p);  // checks the geometry
    cellsim::Simulation check(p, tissue);                        // and the time step's static limit
    std::cout << cellsim::case_to_json(p).dump(2) << "\n";
    return 0;
  }
  if (a.command == "bench") {
    bench(a);
    return 0;
  }
  if (a.command == "run") {
    if (a.output_path.empty()) throw cellsim::InputError("'run' needs an output file: -o OUT.h5");
    cellsim::run_case(load(a), {a.output_path, a.from_path, a.quiet, a.threads});
    return 0;
  }
  throw cellsim::InputError("unknown command '" + a.command + "'\n" + kUsage);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return dispatch(argc, argv);
  } catch (const cellsim::InputError& e) {
    std::cerr << "cellsim: error: " << e.what() << "\n";
    return cellsim::kExitInputError;
  } catch (const cellsim::NumericalFailure& e) {
    std::cerr << "cellsim: numerical failure: " << e.what() << "\n";
    return cellsim::kExitNumericalFailure;
  } catch (const cellsim::FileError& e) {
    std::cerr << "cellsim: file error: " << e.what() << "\n";
    return cellsim::kExitFileError;
  } catch (const std::exception& e) {
    std::cerr << "cellsim: internal error: " << e.what() << "\n";
    return 1;
  }
}
