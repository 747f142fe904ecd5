#pragma once
// What is measured every record (model.md §8): one struct, and one table that names each
// quantity with its unit and definition for the output file and docs/output-reference.md.
#include <string>
#include <vector>

#include "core/params.hpp"
#include "core/state.hpp"
#include "engine/energy_account.hpp"
#include "engine/fluid_model.hpp"
#include "geometry/surface.hpp"
#include "geometry/tissue.hpp"
#include "geometry/wall_mesh.hpp"
#include "physics/eos.hpp"
#include "physics/load_partition.hpp"

namespace cellsim {

struct Record {
  double time_s, stage, step;
  double fluid_mass_kg, fluid_mass_ratio, mean_pressure_Pa;
  double area_m2, volume_m3, fluid_volume_ratio, equivalent_diameter_m, smoothing_length_m;
  double cell_height_m, equatorial_radius_m;
  double max_fluid_speed_m_s, kinetic_energy_fluid_J, kinetic_energy_wall_J, wall_strain_mean;
  double wall_tension_N_m, wall_pressure_Pa;
  double plate_top_z_m, plate_bottom_z_m, plate_force_top_N, plate_force_bottom_N;
  double contact_area_m2, contact_count, contact_area_top_m2;
  double pressure_load_N, load_fluid_N, load_wall_N, load_backstop_N;
  double nominal_strain, plate_strain, plate_stress_Pa, section_stress_Pa, contact_stress_Pa, footprint_stress_Pa;
  double lamella_intact, tissue_volume_m3, porosity;  // a tissue's (model.md §10)
  double gauge_strain;  // the interior layers' strain (strain_gauge.hpp)
  double period_x_m, period_y_m, lateral_stress_Pa;  // a periodic slab's (model.md §10b)
  double relaxation_residual, relaxation_evaluations;  // time.scheme = quasi_static's (quasi_static.hpp)
  // The energy account (energy_account.hpp): each term of core/energy_terms.hpp, their stored sum, the residual.
  EnergyValues energy;
  double stored_energy_J, energy_residual_J;
  double wall_plastic_strain_mean, wall_plastic_strain_max;  // delta_p / l0 over the bonds (wall_plasticity.hpp)
  // Each cell's (model.md §10), in cell order.
  std::vector<double> cell_volume_m3, cell_mean_pressure_Pa, cell_fluid_mass_kg, cell_centroid_z_m, cell_wall_height_m;
  // Each layer's (model.md §10c), from the bottom.
  std::vector<double> layer_centroid_z_m, layer_height_strain;
};

struct Quantity {
  std::string name;  // dataset name under /timeseries
  std::string unit;
  std::string definition;
  double Record::*member = nullptr;  // where the record holds it; null for a term of the energy account,
  int energy_term = -1;             // which sits at this index of Record::energy
  double value(const Record& r) const { return member ? r.*member : r.energy[static_cast<std::size_t>(energy_term)]; }
  double& value(Record& r) const { return member ? r.*member : r.energy[static_cast<std::size_t>(energy_term)]; }
};
const std::vector<Quantity>& quantities();

// The per-cell series: one value per cell in each record (written as records x cells), and the
// per-layer series, written the same way under /layers.
struct CellQuantity {
  std::string name;  // dataset name under /cells (or /layers)
  std::string unit;
  std::string definition;
  std::vector<double> Record::*member;
};
const std::vector<CellQuantity>& cell_quantities();
const std::vector<CellQuantity>& layer_quantities();

// H: max z - min z of the wall particles; the nominal strain (H_c - H) / H_c (model.md §8).
double cell_height_m(const Eigen::Matrix3Xd& wall_x);
inline double nominal_strain(double contact_height_m, double height_m) {
  return (contact_height_m - height_m) / contact_height_m;
}

// The record of state s; area, volume and normals come from its wall surface (surface.hpp), the
// top plate's load partition from the forces of the last step (load_partition.hpp).
Record measure(const State& s, const WallMesh& mesh, const CellRanges& cells, const WallSurface& surface,
               const Params& p, const FluidReadings& fluid, const LoadPartition& load);

// Fills in r's energy account from its terms now (energy_account.hpp) and the stored energy at t = 0.
void add_energy_account(const EnergyValues& terms, double initial_J, Record& r);

std::string output_reference_markdown();

}  // namespace cellsim
