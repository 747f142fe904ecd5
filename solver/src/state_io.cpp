#include "state_io.hpp"

#include <filesystem>

#include "errors.hpp"

namespace cellsim {
namespace {

std::vector<double> flat(const Eigen::Matrix3Xd& m) { return {m.data(), m.data() + m.size()}; }
std::vector<double> flat(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

Eigen::Matrix3Xd read_points(hid_t g, const std::string& name) {
  std::vector<hsize_t> dims;
  const auto data = h5::read_doubles(g, name, &dims);
  if (dims.size() != 2 || dims[1] != 3) throw std::runtime_error(name + " is not an N x 3 array");
  return Eigen::Map<const Eigen::Matrix3Xd>(data.data(), 3, static_cast<Eigen::Index>(dims[0]));
}

Eigen::VectorXd read_vector(hid_t g, const std::string& name) {
  const auto data = h5::read_doubles(g, name);
  return Eigen::Map<const Eigen::VectorXd>(data.data(), static_cast<Eigen::Index>(data.size()));
}

// Plate scalars stored as attributes under their member names.
struct PlateField {
  const char* name;
  double Plates::*member;
};
constexpr PlateField kPlateFields[] = {
    {"plate_axis_x_m", &Plates::axis_x_m},           {"plate_axis_y_m", &Plates::axis_y_m},
    {"plate_bottom_z_m", &Plates::bottom_z_m},       {"plate_top_z_m", &Plates::top_z_m},
    {"plate_top_start_z_m", &Plates::top_start_z_m}, {"plate_start_time_s", &Plates::start_time_s},
    {"plate_force_top_N", &Plates::force_top_N},     {"plate_force_bottom_N", &Plates::force_bottom_N},
    {"plate_contact_height_m", &Plates::contact_height_m},
    {"plate_first_contact_top_z_m", &Plates::first_contact_top_z_m},
};

}  // namespace

void write_state(hid_t parent, const State& s) {
  h5::Handle g = h5::create_group(parent, "state");
  h5::set_attr(g.id(), "time_s", s.time_s);
  h5::set_attr(g.id(), "step", static_cast<std::int64_t>(s.step));
  h5::set_attr(g.id(), "stage_step", static_cast<std::int64_t>(s.stage_step));
  h5::set_attr(g.id(), "stage", static_cast<std::int64_t>(s.stage));
  h5::set_attr(g.id(), "smoothing_length_m", s.smoothing_length_m);
  h5::set_attr(g.id(), "initial_fluid_mass_kg", s.initial_fluid_mass_kg);
  h5::set_attr(g.id(), "wall_mass_kg", s.wall.mass_kg);
  h5::set_attr(g.id(), "plates_active", static_cast<std::int64_t>(s.plates.active));
  h5::set_attr(g.id(), "plate_contacts", static_cast<std::int64_t>(s.plates.contacts));
  for (const auto& field : kPlateFields) h5::set_attr(g.id(), field.name, s.plates.*field.member);
  h5::write(g.id(), "wall_positions", flat(s.wall.x), {static_cast<hsize_t>(s.wall.size()), 3});
  h5::write(g.id(), "wall_velocities", flat(s.wall.v), {static_cast<hsize_t>(s.wall.size()), 3});
  h5::write(g.id(), "fluid_positions", flat(s.fluid.x), {static_cast<hsize_t>(s.fluid.size()), 3});
  h5::write(g.id(), "fluid_velocities", flat(s.fluid.v), {static_cast<hsize_t>(s.fluid.size()), 3});
  h5::write(g.id(), "fluid_mass", flat(s.fluid.m), {static_cast<hsize_t>(s.fluid.size())});
  h5::write(g.id(), "fluid_density", flat(s.fluid.rho), {static_cast<hsize_t>(s.fluid.size())});
}

SavedRun read_saved_run(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError("--from '" + path + "': no such file");
  SavedRun run;
  try {
    h5::Handle file = h5::open_file_readonly(path);
    if (!h5::has_attr(file.id(), "completed") || h5::get_attr_int(file.id(), "completed") != 1)
      throw InputError("--from '" + path + "' is not a completed cellsim result (completed != 1)");
    run.case_json = h5::get_attr_string(file.id(), "case_json");
    h5::Handle g = h5::open_group(file.id(), "state");
    State& s = run.state;
    s.time_s = h5::get_attr_double(g.id(), "time_s");
    s.step = h5::get_attr_int(g.id(), "step");
    s.stage_step = h5::get_attr_int(g.id(), "stage_step");
    s.stage = static_cast<Stage>(h5::get_attr_int(g.id(), "stage"));
    s.smoothing_length_m = h5::get_attr_double(g.id(), "smoothing_length_m");
    s.initial_fluid_mass_kg = h5::get_attr_double(g.id(), "initial_fluid_mass_kg");
    s.wall.mass_kg = h5::get_attr_double(g.id(), "wall_mass_kg");
    s.plates.active = h5::get_attr_int(g.id(), "plates_active") != 0;
    s.plates.contacts = static_cast<int>(h5::get_attr_int(g.id(), "plate_contacts"));
    for (const auto& field : kPlateFields) s.plates.*field.member = h5::get_attr_double(g.id(), field.name);
    s.wall.x = read_points(g.id(), "wall_positions");
    s.wall.v = read_points(g.id(), "wall_velocities");
    s.fluid.x = read_points(g.id(), "fluid_positions");
    s.fluid.v = read_points(g.id(), "fluid_velocities");
    s.fluid.m = read_vector(g.id(), "fluid_mass");
    s.fluid.rho = read_vector(g.id(), "fluid_density");

    h5::Handle ts = h5::open_group(file.id(), "timeseries");
    for (const auto& q : quantities()) {
      const auto column = h5::read_doubles(ts.id(), q.name);
      if (run.records.empty()) run.records.resize(column.size());
      if (column.size() != run.records.size()) throw std::runtime_error("time series of unequal length");
      for (std::size_t r = 0; r < column.size(); ++r) run.records[r].*q.member = column[r];
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError("--from '" + path + "' cannot be read as a cellsim result: " + e.what());
  }
  return run;
}

}  // namespace cellsim
