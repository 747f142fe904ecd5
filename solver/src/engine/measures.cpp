#include "engine/measures.hpp"

#include "engine/strain_gauge.hpp"
#include "geometry/hull.hpp"
#include "physics/plates.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Geometry>

namespace cellsim {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Each cell's volume, mean pressure and fluid mass; a tissue's intact bonds, hull volume and porosity.
void measure_cells(const State& s, const CellRanges& cells, const WallSurface& surface, const FluidReadings& fluid,
                   Record& r) {
  r.cell_volume_m3 = surface.cell_volume_m3;
  r.cell_mean_pressure_Pa = fluid.cell_mean_pressure_Pa;
  r.cell_fluid_mass_kg = fluid.cell_mass_kg;
  const LayerHeights heights = layer_heights(s.wall.x, cells);
  r.cell_centroid_z_m = heights.cell_centroid_z_m;
  r.cell_wall_height_m = heights.cell_height_m;
  r.layer_centroid_z_m = heights.layer_centroid_z_m;
  r.layer_height_strain.assign(heights.layer_height_m.size(), kNaN);
  r.gauge_strain = kNaN;
  r.relaxation_residual = s.relaxation_residual;
  r.relaxation_evaluations = s.relaxation_evaluations;
  r.period_x_m = r.period_y_m = r.lateral_stress_Pa = kNaN;
  if (s.box.periodic()) {
    r.period_x_m = s.box.length_x_m;
    r.period_y_m = s.box.length_y_m;
    r.lateral_stress_Pa = 0.5 * (s.lateral_stress_x_Pa + s.lateral_stress_y_Pa);
  }
  if (s.plates.active) {  // strains from the layers' state when compression started
    for (std::size_t k = 0; k < r.layer_height_strain.size() && k < s.plates.start_layer_height_m.size(); ++k)
      r.layer_height_strain[k] = 1.0 - heights.layer_height_m[k] / s.plates.start_layer_height_m[k];
    r.gauge_strain = 1.0 - gauge_length_m(heights.layer_centroid_z_m) / s.plates.gauge_length_m;
  }
  r.lamella_intact = 0;
  for (char intact : s.lamella_intact) r.lamella_intact += intact;
  r.tissue_volume_m3 = r.porosity = kNaN;
  if (s.box.periodic()) {  // one period of the slab, between its lowest and highest wall particle
    r.tissue_volume_m3 = s.box.area_m2() * (s.wall.x.row(2).maxCoeff() - s.wall.x.row(2).minCoeff());
    r.porosity = 1.0 - surface.volume_m3 / r.tissue_volume_m3;
  } else if (cells.count() > 1) {
    r.tissue_volume_m3 = convex_hull_volume(s.wall.x);
    r.porosity = 1.0 - surface.volume_m3 / r.tissue_volume_m3;
  }
}

// " + "-joined labels of the table's terms of this role (with their signs in the residual: " - " for a loss).
std::string joined_labels(bool stored) {
  std::string text;
  for (const EnergyTerm& term : kEnergyTerms) {
    if ((term.role == EnergyRole::Stored) != stored) continue;
    text += text.empty() ? (term.role == EnergyRole::Loss ? "- " : "") : (term.role == EnergyRole::Loss ? " - " : " + ");
    text += term.label;
  }
  return text;
}

// The energy account's series (docs/model.md §8), from the table of its terms (core/energy_terms.hpp):
// the stored energies, their sum, what the other terms put in since t = 0, and the residual.
void add_energy_quantities(std::vector<Quantity>& q) {
  const auto add_terms = [&](bool stored) {
    for (const EnergyTerm& term : kEnergyTerms)
      if (term.column && (term.role == EnergyRole::Stored) == stored)
        q.push_back({term.column, "J", term.definition, nullptr, static_cast<int>(term.id)});
  };
  add_terms(true);
  q.push_back({"stored_energy_J", "J", "the stored energies' sum: " + joined_labels(true), &Record::stored_energy_J});
  add_terms(false);
  q.push_back({"wall_plastic_strain_mean", "1",
               "mean over the wall bonds of the plastic strain delta_p / l0, the slider's elongation (0 if elastic)",
               &Record::wall_plastic_strain_mean});
  q.push_back({"wall_plastic_strain_max", "1", "largest plastic strain delta_p / l0 of a wall bond (0 if elastic)",
               &Record::wall_plastic_strain_max});
  q.push_back({"energy_residual_J", "J",
               "stored energy - its value at t = 0 - (" + joined_labels(false) + "): the error of the energy account",
               &Record::energy_residual_J});
}
}  // namespace

const std::vector<Quantity>& quantities() {
  static const std::vector<Quantity> all = [] {
    std::vector<Quantity> q = {
      {"time_s", "s", "simulated time since the start of drying", &Record::time_s},
      {"stage", "1", "0 drying, 1 compression", &Record::stage},
      {"step", "1", "time steps done since the start of drying", &Record::step},
      {"fluid_mass_kg", "kg", "total fluid mass (changes by Eq 11)", &Record::fluid_mass_kg},
      {"fluid_mass_ratio", "1", "M_f / M_f0, achieved moisture ratio", &Record::fluid_mass_ratio},
      {"mean_pressure_Pa", "Pa", "arithmetic mean of the fluid particles' EOS pressure (Eq 7)",
       &Record::mean_pressure_Pa},
      {"area_m2", "m^2", "wall area: sum of the wall triangles' areas", &Record::area_m2},
      {"volume_m3", "m^3", "enclosed volume: sum of signed tetrahedra (origin, triangle)", &Record::volume_m3},
      {"fluid_volume_ratio", "1",
       "the fluid's SPH volume sum(m/rho) / the enclosed volume (every cell's): the volume bookkeeping the volume "
       "closure holds during compression", &Record::fluid_volume_ratio},
      {"equivalent_diameter_m", "m", "diameter of the sphere of the enclosed volume (D in Eq 6)",
       &Record::equivalent_diameter_m},
      {"smoothing_length_m", "m", "SPH smoothing length h (Eq 6)", &Record::smoothing_length_m},
      {"cell_height_m", "m", "H: max z - min z of the wall particles", &Record::cell_height_m},
      {"equatorial_radius_m", "m", "largest horizontal distance of a wall particle from the wall centroid's axis",
       &Record::equatorial_radius_m},
      {"kinetic_energy_fluid_J", "J", "sum of m v^2 / 2 over fluid particles", &Record::kinetic_energy_fluid_J},
      {"max_fluid_speed_m_s", "m/s", "speed of the fastest fluid particle", &Record::max_fluid_speed_m_s},
      {"kinetic_energy_wall_J", "J", "sum of m v^2 / 2 over wall particles", &Record::kinetic_energy_wall_J},
      {"wall_strain_mean", "1", "mean bond strain (l - l0) / l0", &Record::wall_strain_mean},
      {"wall_tension_N_m", "N/m", "mean wall tension: sum over bonds of tension x length / (2 x wall area)",
       &Record::wall_tension_N_m},
      {"wall_pressure_Pa", "Pa", "pressure the wall carries: outward LJ push along the vertex normals / wall area",
       &Record::wall_pressure_Pa},
      {"plate_top_z_m", "m", "height of the top plate (NaN before compression)", &Record::plate_top_z_m},
      {"plate_bottom_z_m", "m", "height of the bottom plate (NaN before compression)", &Record::plate_bottom_z_m},
      {"plate_force_top_N", "N", "force of the wall on the top plate, upward positive (Eq 22 reaction)",
       &Record::plate_force_top_N},
      {"plate_force_bottom_N", "N", "force of the wall on the bottom plate, downward positive",
       &Record::plate_force_bottom_N},
      {"contact_area_m2", "m^2", "area (a third of each adjacent triangle) of wall particles within r_pw of a plate",
       &Record::contact_area_m2},
      {"contact_count", "1", "wall particles within r_pw of a plate", &Record::contact_count},
      {"contact_area_top_m2", "m^2", "contact area of the top plate alone (its wall particles' owned area)",
       &Record::contact_area_top_m2},
      {"pressure_load_N", "N", "mean fluid pressure x top contact area: the load a pressurised membrane would carry",
       &Record::pressure_load_N},
      {"load_fluid_N", "N", "upward force of the fluid (wall-fluid coupling) on the wall particles touching the top plate",
       &Record::load_fluid_N},
      {"load_wall_N", "N", "upward force of the wall itself (bonds, bending, damping) on the wall particles touching the top plate",
       &Record::load_wall_N},
      {"load_backstop_N", "N",
       "the part of load_fluid_N the pressure coupling's backstop gives (coupling.backstop_range_over_dx; 0 for LJ)",
       &Record::load_backstop_N},
      {"nominal_strain", "1", "(H_c - H) / H_c, H_c the cell height when compression starts",
       &Record::nominal_strain},
      {"plate_strain", "1", "top-plate travel since first contact / H_c", &Record::plate_strain},
      {"plate_stress_Pa", "Pa", "F_top / (plate length x width); a periodic slab's: F_top / its lateral period's area", &Record::plate_stress_Pa},
      {"section_stress_Pa", "Pa", "F_top / (pi R_c^2), R_c the equatorial radius", &Record::section_stress_Pa},
      {"contact_stress_Pa", "Pa", "F_top / top contact area (NaN without contact)", &Record::contact_stress_Pa},
      {"footprint_stress_Pa", "Pa",
       "F_top / the footprint: the area of the wall's outline seen from above when compression starts, a periodic slab's period (a tissue's stress)",
       &Record::footprint_stress_Pa},
      {"lamella_intact", "1", "middle-lamella bonds between cells not yet broken (0 for one cell)",
       &Record::lamella_intact},
      {"tissue_volume_m3", "m^3", "volume of the convex hull of every wall particle (a tissue's; NaN for one cell); a periodic "
       "slab's: the period's area x the height of its walls",
       &Record::tissue_volume_m3},
      {"gauge_strain", "1",
       "the interior layers' strain 1 - G / G_c, G between the centroid planes of layers 1 and n-2 (four layers "
       "or more; else of the bottom and top layer), G_c when compression started; NaN for one layer and before",
       &Record::gauge_strain},
      {"period_x_m", "m", "a periodic slab's lateral period along x (NaN for a cell or a cluster)", &Record::period_x_m},
      {"period_y_m", "m", "a periodic slab's lateral period along y (NaN for a cell or a cluster)", &Record::period_y_m},
      {"lateral_stress_Pa", "Pa",
       "a periodic slab's lateral stress, tension positive: the mean of its x and y parts, -(virial of the forces "
       "between cells across the period) / (period area x height) (NaN for a cell or a cluster)",
       &Record::lateral_stress_Pa},
      {"porosity", "1", "1 - (sum of the cells' enclosed volumes) / tissue_volume_m3 (NaN for one cell)",
       &Record::porosity},
      {"relaxation_residual", "1",
       "time.scheme = quasi_static: the equilibrium test of the step's relaxation, the largest force on a wall "
       "particle / (max(P_T0, |P|) x the mean area a wall particle owns); at most time.equilibrium_tolerance "
       "(NaN for a dynamic run)",
       &Record::relaxation_residual},
      {"relaxation_evaluations", "1",
       "time.scheme = quasi_static: force evaluations the step's relaxation took (NaN for a dynamic run)",
       &Record::relaxation_evaluations},
    };
    add_energy_quantities(q);
    return q;
  }();
  return all;
}

const std::vector<CellQuantity>& cell_quantities() {
  static const std::vector<CellQuantity> q = {
      {"volume_m3", "m^3", "each cell's enclosed volume (its own wall's signed tetrahedra)", &Record::cell_volume_m3},
      {"mean_pressure_Pa", "Pa", "each cell's mean fluid EOS pressure (Eq 7)", &Record::cell_mean_pressure_Pa},
      {"fluid_mass_kg", "kg", "each cell's fluid mass (Eq 11)", &Record::cell_fluid_mass_kg},
      {"centroid_z_m", "m", "each cell's wall centroid height", &Record::cell_centroid_z_m},
      {"height_m", "m", "each cell's height: max z - min z of its wall particles", &Record::cell_wall_height_m},
  };
  return q;
}

const std::vector<CellQuantity>& layer_quantities() {
  static const std::vector<CellQuantity> q = {
      {"centroid_z_m", "m", "each layer's mean of its cells' wall centroid heights (model.md §10c)",
       &Record::layer_centroid_z_m},
      {"height_strain", "1",
       "each layer's 1 - (mean height of its cells) / (the same when compression started); NaN before",
       &Record::layer_height_strain},
  };
  return q;
}

double cell_height_m(const Eigen::Matrix3Xd& wall_x) { return wall_x.row(2).maxCoeff() - wall_x.row(2).minCoeff(); }

void add_energy_account(const EnergyValues& terms, double initial_J, Record& r) {
  r.energy = terms;
  r.stored_energy_J = stored_energy_J(terms);
  r.energy_residual_J = energy_residual_J(terms, initial_J);
}

Record measure(const State& s, const WallMesh& mesh, const CellRanges& cells, const WallSurface& surface,
               const Params& p, const FluidReadings& fluid, const LoadPartition& load) {
  Record r{};
  measure_cells(s, cells, surface, fluid, r);
  const auto& w = s.wall;
  r.time_s = s.time_s;
  r.stage = static_cast<double>(s.stage);
  r.step = static_cast<double>(s.step);
  r.fluid_mass_kg = fluid.mass_kg;
  r.fluid_mass_ratio = r.fluid_mass_kg / s.initial_fluid_mass_kg;
  r.max_fluid_speed_m_s = fluid.max_speed_m_s;
  r.mean_pressure_Pa = fluid.mean_pressure_Pa;
  r.area_m2 = surface.area_m2;
  r.volume_m3 = surface.volume_m3;
  r.fluid_volume_ratio = fluid.volume_ratio;
  r.equivalent_diameter_m = equivalent_diameter_m(r.volume_m3);
  r.smoothing_length_m = s.smoothing_length_m;
  r.cell_height_m = cell_height_m(w.x);
  const Eigen::Vector3d centroid = w.x.rowwise().mean();
  r.equatorial_radius_m = (w.x.topRows<2>().colwise() - centroid.head<2>()).colwise().norm().maxCoeff();
  r.kinetic_energy_fluid_J = fluid.kinetic_energy_J;
  r.kinetic_energy_wall_J = 0.5 * w.mass_kg * w.v.squaredNorm();
  double strain_sum = 0;
  for (std::size_t b = 0; b < mesh.bonds.size(); ++b) {
    const double l = (w.x.col(mesh.bonds[b][0]) - w.x.col(mesh.bonds[b][1])).norm();
    strain_sum += (l - mesh.rest_length_m[b]) / mesh.rest_length_m[b];
  }
  r.wall_plastic_strain_mean = r.wall_plastic_strain_max = 0;
  for (std::size_t b = 0; b < mesh.bonds.size(); ++b) {
    const double plastic = s.bond_plastic_elongation_m[b] / mesh.rest_length_m[b];
    r.wall_plastic_strain_mean += plastic / static_cast<double>(mesh.bonds.size());
    r.wall_plastic_strain_max = std::max(r.wall_plastic_strain_max, plastic);
  }
  r.wall_tension_N_m = s.wall_tension_N_m;
  r.wall_pressure_Pa = s.wall_pressure_Pa;
  r.wall_strain_mean = mesh.bonds.empty() ? 0.0 : strain_sum / static_cast<double>(mesh.bonds.size());

  const Plates& pl = s.plates;
  if (!pl.active) {
    r.plate_top_z_m = r.plate_bottom_z_m = r.plate_force_top_N = r.plate_force_bottom_N = kNaN;
    r.contact_area_m2 = r.contact_count = r.contact_area_top_m2 = kNaN;
    r.pressure_load_N = r.load_fluid_N = r.load_wall_N = r.load_backstop_N = kNaN;
    r.nominal_strain = r.plate_strain = r.plate_stress_Pa = r.section_stress_Pa = r.contact_stress_Pa = kNaN;
    r.footprint_stress_Pa = kNaN;
    return r;
  }
  r.plate_top_z_m = pl.top_z_m;
  r.plate_bottom_z_m = pl.bottom_z_m;
  r.plate_force_top_N = pl.force_top_N;
  r.plate_force_bottom_N = pl.force_bottom_N;
  // Contact area: the area owned by the wall particles that Eq 22 pushes (plates.hpp decides).
  const Eigen::VectorXd vertex_area = surface.vertex_areas(mesh);
  const PlateLaw law = plate_law(p);
  double contact_area = 0, contact_area_top = 0;
  int contacts = 0;
  for (Eigen::Index k = 0; k < w.size(); ++k) {
    const PlateOverlap overlap = plate_overlap(w.x.col(k), law, pl);
    if (!overlap.touches()) continue;
    contact_area += vertex_area[k];
    ++contacts;
    if (overlap.top_m > 0) contact_area_top += vertex_area[k];
  }
  r.contact_area_m2 = contact_area;
  r.contact_count = contacts;
  const double hc = pl.contact_height_m;
  r.nominal_strain = nominal_strain(hc, r.cell_height_m);
  r.plate_strain = std::isnan(pl.first_contact_top_z_m) ? 0.0 : (pl.first_contact_top_z_m - pl.top_z_m) / hc;
  // over the plate's area, or a periodic slab's period (model.md §10b)
  r.plate_stress_Pa = pl.force_top_N / (s.box.periodic() ? s.box.area_m2() : p.plate_length_m * p.plate_width_m);
  r.section_stress_Pa = pl.force_top_N / (M_PI * r.equatorial_radius_m * r.equatorial_radius_m);
  r.footprint_stress_Pa = pl.force_top_N / pl.footprint_m2;
  r.contact_area_top_m2 = contact_area_top;
  r.pressure_load_N = r.mean_pressure_Pa * contact_area_top;
  r.load_fluid_N = load.fluid_push_N;
  r.load_wall_N = load.wall_push_N;
  r.load_backstop_N = load.backstop_push_N;
  // The top plate's force over the top plate's own contact (the bottom one carries the same load).
  r.contact_stress_Pa = contact_area_top > 0 ? pl.force_top_N / contact_area_top : kNaN;
  return r;
}

std::string output_reference_markdown() {
  std::ostringstream s;
  s << "| dataset | unit | definition |\n|---|---|---|\n";
  for (const auto& q : quantities()) s << "| `/timeseries/" << q.name << "` | " << q.unit << " | " << q.definition << " |\n";
  for (const auto& q : cell_quantities())
    s << "| `/cells/" << q.name << "` | " << q.unit << " | " << q.definition << ", records x cells |\n";
  for (const auto& q : layer_quantities())
    s << "| `/layers/" << q.name << "` | " << q.unit << " | " << q.definition << ", records x layers |\n";
  return s.str();
}

}  // namespace cellsim
