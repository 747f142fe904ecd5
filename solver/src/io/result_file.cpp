#include "io/result_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "core/errors.hpp"
#include "io/h5_eigen.hpp"
#include "io/state_io.hpp"
#include "io/version.hpp"

namespace cellsim {
namespace {

// Renames, saying what the system said when it cannot.
void rename_or_throw(const std::string& from, const std::string& to) {
  std::error_code error;
  std::filesystem::rename(from, to, error);
  if (error) throw FileError("cannot rename '" + from + "' to '" + to + "': " + error.message());
}

void write_text_file(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".partial";
  {
    errno = 0;
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.flush();
    if (!out)
      throw FileError("cannot write '" + tmp + "'" + (errno ? std::string(": ") + std::strerror(errno) : std::string()));
  }
  rename_or_throw(tmp, path);
}

}  // namespace

ResultFile::ResultFile(const std::string& final_path)
    : final_path_(final_path), partial_path_(final_path + ".partial") {
  const auto dir = std::filesystem::path(final_path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw InputError("output '" + final_path + "': directory '" + dir.string() + "' does not exist");
  if (std::filesystem::is_directory(final_path))
    throw InputError("output '" + final_path + "' is a directory; give a file name such as run.h5");
  try {
    file_ = h5::create_file(partial_path_);
  } catch (const FileError& e) {
    throw FileError("output '" + final_path + "': " + e.what());
  }
  h5::set_attr(file_.id(), "completed", std::int64_t{0});
}

ResultFile::~ResultFile() = default;

void ResultFile::write_header(const nlohmann::json& resolved_case, int threads) {
  const hid_t root = file_.id();
  h5::set_attr(root, "case_json", resolved_case.dump(2));
  h5::set_attr(root, "solver", std::string("cellsim"));
  h5::set_attr(root, "solver_version", std::string(kVersion));
  h5::set_attr(root, "git_revision", std::string(kGitRevision));
  h5::set_attr(root, "instruction_set", std::string(kInstructionSet));
  h5::set_attr(root, "threads", std::int64_t{threads});  // results are bit-identical only for the same count
  h5::set_attr(root, "units", std::string("SI throughout; each dataset carries a 'unit' attribute"));
  snapshots_ = h5::create_group(root, "snapshots");
}

void ResultFile::write_run_summary(const DryingSummary& d, const CompressionSummary& c) {
  cellsim::write_run_summary(file_.id(), d, c);
}

void ResultFile::write_mesh(const WallMesh& mesh, const CellRanges& cells, const std::vector<LamellaBond>& lamella) {
  const long n_fluid = static_cast<long>(cells.fluid.back());
  h5::Handle g = h5::create_group(file_.id(), "mesh");
  std::vector<std::int32_t> tri, bonds, hinges, fluid_vertices;
  for (const auto& t : mesh.triangles) tri.insert(tri.end(), t.begin(), t.end());
  for (const auto& b : mesh.bonds) bonds.insert(bonds.end(), b.begin(), b.end());
  for (const auto& h : mesh.hinges) hinges.insert(hinges.end(), {h.a, h.b, h.c, h.d});
  for (long i = 0; i < n_fluid; ++i) fluid_vertices.push_back(static_cast<std::int32_t>(i));
  h5::write(g.id(), "triangles", tri, {mesh.triangles.size(), 3});
  h5::write(g.id(), "bonds", bonds, {mesh.bonds.size(), 2});
  h5::write(g.id(), "hinges", hinges, {mesh.hinges.size(), 4});
  h5::write(g.id(), "bond_rest_length", mesh.rest_length_m, {mesh.rest_length_m.size()});
  h5::write(g.id(), "fluid_vertices", fluid_vertices, {fluid_vertices.size(), 1});
  const auto as_int32 = [](const std::vector<int>& v) { return std::vector<std::int32_t>(v.begin(), v.end()); };
  h5::write(g.id(), "wall_cell", as_int32(cells.cell_of_wall()), {static_cast<std::size_t>(cells.wall.back())});
  h5::write(g.id(), "fluid_cell", as_int32(cells.cell_of_fluid()), {static_cast<std::size_t>(n_fluid)});
  h5::set_dataset_attr(g.id(), "wall_cell", "description", "the cell of each wall particle (0 for one cell)");
  h5::set_dataset_attr(g.id(), "fluid_cell", "description", "the cell of each fluid particle (0 for one cell)");
  if (!lamella.empty()) {
    std::vector<std::int32_t> pairs;
    std::vector<double> length;
    for (const auto& b : lamella) pairs.insert(pairs.end(), {b.a, b.b}), length.push_back(b.length_m);
    h5::write(g.id(), "lamella", pairs, {lamella.size(), 2});
    h5::write(g.id(), "lamella_rest_length", length, {lamella.size()});
    h5::set_dataset_attr(g.id(), "lamella", "description", "middle-lamella bonds: wall particles of two cells");
    h5::set_dataset_attr(g.id(), "lamella_rest_length", "unit", "m");
  }
  h5::set_dataset_attr(g.id(), "triangles", "description", "wall particle indices, outward (counter-clockwise)");
  h5::set_dataset_attr(g.id(), "hinges", "description", "edge (a, b) shared by triangles (a, b, c) and (b, a, d)");
  h5::set_dataset_attr(g.id(), "bond_rest_length", "unit", "m");
  n_triangles_ = static_cast<long>(mesh.triangles.size());
  n_fluid_ = n_fluid;
}

void ResultFile::write_snapshot(const State& s, const EquationOfState& eos) {
  std::ostringstream name;
  name << std::setw(9) << std::setfill('0') << s.step;
  // A numerical failure in the first half of the step after a snapshot comes before that step is
  // counted: its state (run.cpp saves it for diagnosis) goes beside the snapshot of the same count.
  if (h5::exists(snapshots_.id(), name.str())) name << "_failed";
  h5::Handle g = h5::create_group(snapshots_.id(), name.str());
  h5::set_attr(g.id(), "time_s", s.time_s);
  h5::set_attr(g.id(), "step", static_cast<std::int64_t>(s.step));
  h5::set_attr(g.id(), "stage", static_cast<std::int64_t>(s.stage));
  h5::set_attr(g.id(), "plate_top_z_m", s.plates.active ? s.plates.top_z_m : std::nan(""));
  h5::set_attr(g.id(), "plate_bottom_z_m", s.plates.active ? s.plates.bottom_z_m : std::nan(""));
  const auto& f = s.fluid;
  const auto& w = s.wall;
  Eigen::VectorXd pressure(f.size());
  for (Eigen::Index i = 0; i < f.size(); ++i) pressure[i] = eos.pressure(f.rho[i]);
  h5::write_points(g.id(), "wall_positions", w.x);
  h5::write_points(g.id(), "wall_velocities", w.v);
  h5::write_points(g.id(), "fluid_positions", f.x);
  h5::write_points(g.id(), "fluid_velocities", f.v);
  h5::write_values(g.id(), "fluid_mass", f.m);
  h5::write_values(g.id(), "fluid_density", f.rho);
  h5::write_values(g.id(), "fluid_pressure", pressure);
  for (const char* d : {"wall_positions", "fluid_positions"}) h5::set_dataset_attr(g.id(), d, "unit", "m");
  for (const char* d : {"wall_velocities", "fluid_velocities"}) h5::set_dataset_attr(g.id(), d, "unit", "m/s");
  h5::set_dataset_attr(g.id(), "fluid_mass", "unit", "kg");
  h5::set_dataset_attr(g.id(), "fluid_density", "unit", "kg/m^3");
  h5::set_dataset_attr(g.id(), "fluid_pressure", "unit", "Pa");
  n_wall_ = static_cast<long>(w.size());
  snapshot_list_.push_back({"/snapshots/" + name.str(), s.time_s});
}

void ResultFile::write_timeseries(const std::vector<Record>& records) {
  h5::Handle g = h5::create_group(file_.id(), "timeseries");
  for (const auto& q : quantities()) {
    std::vector<double> column;
    column.reserve(records.size());
    for (const auto& r : records) column.push_back(q.value(r));
    h5::write(g.id(), q.name, column, {column.size()});
    h5::set_dataset_attr(g.id(), q.name, "unit", q.unit);
    h5::set_dataset_attr(g.id(), q.name, "definition", q.definition);
  }
  // Each cell's series (records x cells), and each layer's (records x layers).
  for (const auto& [group_name, list] : {std::pair{"cells", &cell_quantities()}, std::pair{"layers", &layer_quantities()}}) {
    h5::Handle group = h5::create_group(file_.id(), group_name);
    for (const auto& q : *list) {
      const std::size_t columns = records.empty() ? 0 : (records.front().*q.member).size();
      std::vector<double> table;
      table.reserve(records.size() * columns);
      for (const auto& r : records) table.insert(table.end(), (r.*q.member).begin(), (r.*q.member).end());
      h5::write(group.id(), q.name, table, {records.size(), columns});
      h5::set_dataset_attr(group.id(), q.name, "unit", q.unit);
      h5::set_dataset_attr(group.id(), q.name, "definition", q.definition);
    }
  }
}

void ResultFile::complete(const std::vector<Record>& records, const State& final_state) {
  write_timeseries(records);
  write_state(file_.id(), final_state);
  h5::set_attr(file_.id(), "completed", std::int64_t{1});  // last: the file is whole
  snapshots_.close();
  file_.close();
  rename_or_throw(partial_path_, final_path_);
  const std::string h5_name = std::filesystem::path(final_path_).filename().string();
  const std::string stem = final_path_.substr(0, final_path_.size() - std::filesystem::path(final_path_).extension().string().size());
  write_text_file(stem + ".wall.xdmf", xdmf_text("wall", h5_name, snapshot_list_, n_wall_, n_triangles_));
  write_text_file(stem + ".fluid.xdmf", xdmf_text("fluid", h5_name, snapshot_list_, n_fluid_, 0));
  done_ = true;
}

void ResultFile::fail(const std::vector<Record>& records, const std::string& message) {
  if (done_ || file_.id() < 0) return;
  try {
    write_timeseries(records);
  } catch (const std::exception&) {
    // A failure while the time series group exists already: keep the message below anyway.
  }
  h5::set_attr(file_.id(), "failure", message);
  snapshots_.close();
  file_.close();
  done_ = true;
}

}  // namespace cellsim
