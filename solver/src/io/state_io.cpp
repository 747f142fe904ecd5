#include "io/state_io.hpp"

#include <cmath>
#include <filesystem>
#include <string>

#include "core/errors.hpp"
#include "engine/step_checks.hpp"
#include "io/h5_eigen.hpp"

namespace cellsim {
namespace {

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
    {"plate_contact_height_m", &Plates::contact_height_m}, {"plate_footprint_m2", &Plates::footprint_m2},
    {"plate_first_contact_top_z_m", &Plates::first_contact_top_z_m},
    {"plate_gauge_length_m", &Plates::gauge_length_m},
};

}  // namespace

void write_run_summary(hid_t parent, const DryingSummary& d, const CompressionSummary& c) {  // drying: read_saved_run
  h5::set_attr(parent, "settle_iterations", std::int64_t{d.settle.iterations});
  h5::set_attr(parent, "settle_residual", d.settle.residual);
  h5::set_attr(parent, "settle_converged", std::int64_t{d.settle.converged});
  h5::set_attr(parent, "settle_mass_ratio", d.settle.mass_ratio);
  h5::set_attr(parent, "settle_volume_ratio", d.settle.volume_ratio);
  h5::set_attr(parent, "drying_steady", std::int64_t{d.steady});
  h5::set_attr(parent, "drying_steady_time_s", d.steady_time_s);
  h5::set_attr(parent, "volumetric_modulus_Pa", d.volumetric_modulus_Pa);
  h5::set_attr(parent, "drying_energy_residual_share", d.energy_residual_share);
  h5::set_attr(parent, "compression_energy_residual_share", c.energy_residual_share);
  h5::set_attr(parent, "compression_reached_end", c.reached_code());
  h5::set_attr(parent, "compression_end_strain", c.strain);
  const std::string joined = d.warning() + (d.warning().empty() || c.warning().empty() ? "" : "; ") + c.warning();
  h5::set_attr(parent, "warning", joined);
}

void write_state(hid_t parent, const State& s) {
  h5::Handle g = h5::create_group(parent, "state");
  h5::set_attr(g.id(), "time_s", s.time_s);
  h5::set_attr(g.id(), "step", static_cast<std::int64_t>(s.step));
  h5::set_attr(g.id(), "stage_step", static_cast<std::int64_t>(s.stage_step));
  h5::set_attr(g.id(), "stage", static_cast<std::int64_t>(s.stage));
  h5::set_attr(g.id(), "smoothing_length_m", s.smoothing_length_m);
  h5::set_attr(g.id(), "initial_fluid_mass_kg", s.initial_fluid_mass_kg);
  h5::set_attr(g.id(), "reference_diameter_m", s.reference_diameter_m);
  h5::set_attr(g.id(), "wall_mass_kg", s.wall.mass_kg);
  h5::set_attr(g.id(), "plates_active", static_cast<std::int64_t>(s.plates.active));
  h5::set_attr(g.id(), "plate_contacts", static_cast<std::int64_t>(s.plates.contacts));
  h5::set_attr(g.id(), "box_length_x_m", s.box.length_x_m);
  h5::set_attr(g.id(), "box_length_y_m", s.box.length_y_m);
  for (const auto& field : kPlateFields) h5::set_attr(g.id(), field.name, s.plates.*field.member);
  // The energy account's running integrals (state.hpp), each under its term's state key.
  h5::set_attr(g.id(), "energy_initial_J", s.energy.initial_J);
  for (const EnergyTerm& term : kEnergyTerms)
    if (integrated(term)) h5::set_attr(g.id(), term.state_key, s.energy.integral[term.id]);
  h5::write_points(g.id(), "wall_positions", s.wall.x);
  h5::write_points(g.id(), "wall_velocities", s.wall.v);
  h5::write_points(g.id(), "fluid_positions", s.fluid.x);
  h5::write_points(g.id(), "fluid_velocities", s.fluid.v);
  h5::write_values(g.id(), "fluid_mass", s.fluid.m);
  h5::write_values(g.id(), "fluid_density", s.fluid.rho);
  if (!s.lamella_intact.empty())  // a tissue's bonds: which still hold (1) and which broke (0)
    h5::write(g.id(), "lamella_intact", std::vector<std::int32_t>(s.lamella_intact.begin(), s.lamella_intact.end()),
              {s.lamella_intact.size()});
  if (!s.lamella_peak_opening_m.empty())
    h5::write(g.id(), "lamella_peak_opening", s.lamella_peak_opening_m, {s.lamella_peak_opening_m.size()});
  if (!s.plates.start_layer_height_m.empty())
    h5::write(g.id(), "start_layer_height", s.plates.start_layer_height_m, {s.plates.start_layer_height_m.size()});
  if (!s.cavity_mass_kg.empty())  // a closed cell's fluid (fluid.model = cavity): one mass per cell
    h5::write(g.id(), "cavity_mass", s.cavity_mass_kg, {s.cavity_mass_kg.size()});
  // the sliders: the plastic set a continued run carries
  h5::write(g.id(), "bond_plastic_elongation", s.bond_plastic_elongation_m, {s.bond_plastic_elongation_m.size()});
}

SavedRun read_saved_run(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError("--from '" + path + "': no such file");
  SavedRun run;
  try {
    h5::Handle file = h5::open_file_readonly(path);
    if (!h5::has_attr(file.id(), "completed") || h5::get_attr_int(file.id(), "completed") != 1)
      throw InputError("--from '" + path + "' is not a completed cellsim result (completed != 1)");
    run.case_doc = nlohmann::json::parse(h5::get_attr_string(file.id(), "case_json"));
    if (h5::has_attr(file.id(), "threads")) run.threads = static_cast<int>(h5::get_attr_int(file.id(), "threads"));
    DryingSummary& d = run.drying;  // as write_drying_summary wrote it
    d.settle.iterations = h5::get_attr_int(file.id(), "settle_iterations");
    d.settle.residual = h5::get_attr_double(file.id(), "settle_residual");
    d.settle.converged = h5::get_attr_int(file.id(), "settle_converged") != 0;
    d.settle.mass_ratio = h5::get_attr_double(file.id(), "settle_mass_ratio");
    d.settle.volume_ratio = h5::get_attr_double(file.id(), "settle_volume_ratio");
    d.steady = h5::get_attr_int(file.id(), "drying_steady") != 0;
    d.steady_time_s = h5::get_attr_double(file.id(), "drying_steady_time_s");
    if (h5::has_attr(file.id(), "volumetric_modulus_Pa"))  // written before issue 46: none
      d.volumetric_modulus_Pa = h5::get_attr_double(file.id(), "volumetric_modulus_Pa");
    if (h5::has_attr(file.id(), "drying_energy_residual_share"))  // written before issue 67: none
      d.energy_residual_share = h5::get_attr_double(file.id(), "drying_energy_residual_share");
    h5::Handle g = h5::open_group(file.id(), "state");
    State& s = run.state;
    s.time_s = h5::get_attr_double(g.id(), "time_s");
    s.step = h5::get_attr_int(g.id(), "step");
    s.stage_step = h5::get_attr_int(g.id(), "stage_step");
    s.stage = static_cast<Stage>(h5::get_attr_int(g.id(), "stage"));
    s.smoothing_length_m = h5::get_attr_double(g.id(), "smoothing_length_m");
    s.initial_fluid_mass_kg = h5::get_attr_double(g.id(), "initial_fluid_mass_kg");
    s.reference_diameter_m = h5::get_attr_double(g.id(), "reference_diameter_m");
    s.wall.mass_kg = h5::get_attr_double(g.id(), "wall_mass_kg");
    s.plates.active = h5::get_attr_int(g.id(), "plates_active") != 0;
    s.plates.contacts = static_cast<int>(h5::get_attr_int(g.id(), "plate_contacts"));
    if (h5::has_attr(g.id(), "box_length_x_m")) {  // written before periodic tissues: no period
      s.box.length_x_m = h5::get_attr_double(g.id(), "box_length_x_m");
      s.box.length_y_m = h5::get_attr_double(g.id(), "box_length_y_m");
    }
    for (const auto& field : kPlateFields)  // a field added since the file was written: none
      s.plates.*field.member = h5::has_attr(g.id(), field.name) ? h5::get_attr_double(g.id(), field.name) : std::nan("");
    const auto energy = [&](const char* key) {  // a term added since the file was written started at 0
      return h5::has_attr(g.id(), key) ? h5::get_attr_double(g.id(), key) : 0.0;
    };
    s.energy.initial_J = energy("energy_initial_J");
    for (const EnergyTerm& term : kEnergyTerms)
      if (integrated(term)) s.energy.integral[term.id] = energy(term.state_key);
    if (h5::exists(g.id(), "start_layer_height"))
      s.plates.start_layer_height_m = h5::read_doubles(g.id(), "start_layer_height");
    if (h5::exists(g.id(), "bond_plastic_elongation"))
      s.bond_plastic_elongation_m = h5::read_doubles(g.id(), "bond_plastic_elongation");
    if (h5::exists(g.id(), "cavity_mass")) s.cavity_mass_kg = h5::read_doubles(g.id(), "cavity_mass");
    s.wall.x = h5::read_points(g.id(), "wall_positions");
    s.wall.v = h5::read_points(g.id(), "wall_velocities");
    s.fluid.x = h5::read_points(g.id(), "fluid_positions");
    s.fluid.v = h5::read_points(g.id(), "fluid_velocities");
    s.fluid.m = h5::read_values(g.id(), "fluid_mass");
    s.fluid.rho = h5::read_values(g.id(), "fluid_density");
    if (h5::exists(g.id(), "lamella_intact")) {
      const std::vector<std::int32_t> intact = h5::read_ints(g.id(), "lamella_intact");
      s.lamella_intact.assign(intact.begin(), intact.end());
      s.lamella_peak_opening_m = h5::exists(g.id(), "lamella_peak_opening")
                                     ? h5::read_doubles(g.id(), "lamella_peak_opening")
                                     : std::vector<double>(intact.size(), 0.0);  // saved before the bond law had damage
    }

    h5::Handle ts = h5::open_group(file.id(), "timeseries");
    for (const auto& q : quantities()) {
      const auto column = h5::read_doubles(ts.id(), q.name);
      if (run.records.empty()) run.records.resize(column.size());
      if (column.size() != run.records.size()) throw std::runtime_error("time series of unequal length");
      for (std::size_t r = 0; r < column.size(); ++r) q.value(run.records[r]) = column[r];
    }
    // The last record is taken at the state's step (run.cpp): a series that ends elsewhere was changed on
    // disk (a zeroed chunk with its checksum passes Fletcher-32; found by the fuzz corpus).
    if (!run.records.empty() && (run.records.back().time_s != s.time_s ||
                                 run.records.back().step != static_cast<double>(s.step)))
      throw std::runtime_error("its time series does not end at its state's time and step (damaged)");
    for (const auto& [group_name, list] : {std::pair{"cells", &cell_quantities()}, std::pair{"layers", &layer_quantities()}}) {
      if (!h5::exists(file.id(), group_name)) continue;  // written before the layers were
      h5::Handle group = h5::open_group(file.id(), group_name);
      for (const auto& q : *list) {
        if (!h5::exists(group.id(), q.name)) continue;  // a series added since the file was written
        std::vector<hsize_t> dims;
        const auto table = h5::read_doubles(group.id(), q.name, &dims);
        if (dims.size() != 2 || dims[0] != run.records.size())
          throw std::runtime_error(std::string("per-") + group_name + " series of unequal length");
        for (std::size_t r = 0; r < run.records.size(); ++r)
          (run.records[r].*q.member).assign(table.begin() + static_cast<std::ptrdiff_t>(r * dims[1]),
                                            table.begin() + static_cast<std::ptrdiff_t>((r + 1) * dims[1]));
      }
    }
  } catch (const InputError&) {
    throw;
  } catch (const FileError& e) {
    throw FileError(std::string("--from: ") + e.what());
  } catch (const std::exception& e) {
    throw InputError("--from '" + path + "' cannot be read as a cellsim result: " + e.what());
  }
  return run;
}

void check_restorable(const State& saved, const State& built, std::size_t wall_bonds) {
  if (saved.fluid.size() != built.fluid.size() || saved.wall.size() != built.wall.size() ||
      saved.lamella_intact.size() != built.lamella_intact.size())
    throw InputError("saved state has " + std::to_string(saved.fluid.size()) + " fluid and " +
                     std::to_string(saved.wall.size()) + " wall particles and " +
                     std::to_string(saved.lamella_intact.size()) + " lamella bonds; the case builds " +
                     std::to_string(built.fluid.size()) + ", " + std::to_string(built.wall.size()) + " and " +
                     std::to_string(built.lamella_intact.size()));
  if (saved.box.periodic() != built.box.periodic())
    throw InputError(std::string("saved state is of a ") + (saved.box.periodic() ? "periodic" : "non-periodic") +
                     " tissue; the case builds a " + (built.box.periodic() ? "periodic" : "non-periodic") +
                     " one (tissue.lateral)");
  // Every per-particle and per-bond array as long as its particles or bonds (a file cut or edited
  // by hand can hold one shorter than the others; found by the fuzzer, issue 51).
  const auto same = [](const char* what, Eigen::Index have, Eigen::Index want) {
    if (have != want)
      throw InputError(std::string("saved state has ") + std::to_string(have) + " " + what + "; the case builds " +
                       std::to_string(want));
  };
  const auto& f = saved.fluid;
  const auto& w = saved.wall;
  same("fluid velocities", f.v.cols(), f.x.cols());
  same("fluid masses", f.m.size(), f.x.cols());
  same("fluid densities", f.rho.size(), f.x.cols());
  same("wall velocities", w.v.cols(), w.x.cols());
  same("lamella openings", static_cast<Eigen::Index>(saved.lamella_peak_opening_m.size()),
       static_cast<Eigen::Index>(saved.lamella_intact.size()));
  same("closed-cell fluid masses", static_cast<Eigen::Index>(saved.cavity_mass_kg.size()),
       static_cast<Eigen::Index>(built.cavity_mass_kg.size()));
  for (double mass : saved.cavity_mass_kg)
    if (!(mass > 0) || !std::isfinite(mass)) throw InputError("saved state has a closed-cell fluid mass that is not positive");
  if (!saved.bond_plastic_elongation_m.empty())  // empty: saved before the wall could yield
    same("wall bonds", static_cast<Eigen::Index>(saved.bond_plastic_elongation_m.size()),
         static_cast<Eigen::Index>(wall_bonds));
  if (!fluid_is_sound(f, 0, f.size()) || !wall_is_finite(w, 0, w.size()))
    throw InputError("saved state has a non-finite position or velocity, or a density or mass that is not positive");
  const auto finite = [](const std::vector<double>& v) {
    return all_finite(Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())));
  };
  if (!finite(saved.lamella_peak_opening_m) || !finite(saved.bond_plastic_elongation_m) ||
      !finite(saved.plates.start_layer_height_m))
    throw InputError("saved state has a non-finite lamella opening, plastic elongation or layer height");
  const bool scalars_sound = std::isfinite(saved.time_s) && saved.smoothing_length_m > 0 &&
                             saved.initial_fluid_mass_kg > 0 && saved.reference_diameter_m > 0 && w.mass_kg > 0 &&
                             std::isfinite(saved.smoothing_length_m) && std::isfinite(saved.initial_fluid_mass_kg) &&
                             std::isfinite(saved.reference_diameter_m) && std::isfinite(w.mass_kg) &&
                             std::isfinite(saved.box.length_x_m) && std::isfinite(saved.box.length_y_m);
  if (!scalars_sound)
    throw InputError("saved state has a time, smoothing length, mass, diameter or period that is not finite (or "
                     "not positive)");
}

}  // namespace cellsim
