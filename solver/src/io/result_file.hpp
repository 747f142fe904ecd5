#pragma once
// One HDF5 result file per run (docs/output-reference.md). It is written under
// OUT.partial and renamed to OUT only when complete; the XDMF sidecars follow the rename.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/state.hpp"
#include "engine/measures.hpp"
#include "geometry/tissue.hpp"
#include "geometry/wall_mesh.hpp"
#include "io/compression_summary.hpp"
#include "io/drying_summary.hpp"
#include "io/h5.hpp"
#include "io/xdmf.hpp"
#include "physics/eos.hpp"

namespace cellsim {

class ResultFile {
 public:
  // Creates OUT.partial at once, so an unwritable path fails before any work (InputError).
  explicit ResultFile(const std::string& final_path);
  ~ResultFile();  // an unfinished file stays under its .partial name, marked completed = 0
  ResultFile(const ResultFile&) = delete;
  ResultFile& operator=(const ResultFile&) = delete;

  void write_header(const nlohmann::json& resolved_case, int threads);  // threads: of the fluid pair loop
  // The wall's triangles, bonds and hinges, each particle's cell, and a tissue's middle-lamella bonds.
  void write_mesh(const WallMesh& mesh, const CellRanges& cells, const std::vector<LamellaBond>& lamella);
  void write_run_summary(const DryingSummary& d, const CompressionSummary& c);
  void write_snapshot(const State& s, const EquationOfState& eos);
  // Time series, the state to continue from, completed = 1; then rename and write the sidecars.
  void complete(const std::vector<Record>& records, const State& final_state);
  // Time series so far and the failure message; completed stays 0 and the name stays .partial.
  void fail(const std::vector<Record>& records, const std::string& message);

  const std::string& partial_path() const { return partial_path_; }

 private:
  void write_timeseries(const std::vector<Record>& records);

  std::string final_path_, partial_path_;
  h5::Handle file_;
  h5::Handle snapshots_;
  std::vector<SnapshotInfo> snapshot_list_;
  long n_wall_ = 0, n_fluid_ = 0, n_triangles_ = 0;
  bool done_ = false;
};

}  // namespace cellsim
