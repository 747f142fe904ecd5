#pragma once
// The evolving state of one run: particles as structure-of-arrays, indices stable for the whole run
// (a tissue's cells one after another: tissue.hpp).
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include "core/energy_terms.hpp"
#include "core/periodic_box.hpp"

namespace cellsim {

enum class Stage : int { Drying = 0, Compression = 1 };

struct FluidParticles {
  Eigen::Matrix3Xd x, v;   // position [m], velocity [m/s]
  Eigen::VectorXd m;       // mass [kg] (changes by Eq 11)
  Eigen::VectorXd rho;     // density [kg/m^3] (continuity, Eqs 9-10)
  Eigen::Index size() const { return x.cols(); }
};

struct WallParticles {
  Eigen::Matrix3Xd x, v;   // position [m], velocity [m/s]
  double mass_kg = 0;      // equal for every wall particle
  Eigen::Index size() const { return x.cols(); }
};

struct Plates {
  bool active = false;            // only during compression
  double axis_x_m = 0, axis_y_m = 0;  // centre of the plates' footprint (the cell's centroid at the start)
  double bottom_z_m = 0;          // plane of the fixed bottom plate
  double top_z_m = 0;             // plane of the moving top plate
  double top_start_z_m = 0;
  double start_time_s = 0;        // when compression started
  double force_top_N = 0;         // force of the wall on the top plate, upward positive
  double force_bottom_N = 0;      // force of the wall on the bottom plate, downward positive
  int contacts = 0;               // wall particles within r_pw of either plate
  double contact_height_m = 0;    // H_c: cell height when compression starts
  double footprint_m2 = 0;        // area of the wall's outline seen from above when compression starts
  double first_contact_top_z_m = 0;  // top plate height at first contact (NaN before)
  // The strain gauge's references when compression starts (engine/strain_gauge.hpp): its length, and
  // each layer's mean cell height.
  double gauge_length_m = 0;
  std::vector<double> start_layer_height_m;
  // Load-unload (compression.unload_at_strain): from unload_start_time_s on, the top plate moves back up
  // (physics/plate_motion.hpp).
  bool unloading = false;
  double unload_start_time_s = 0, unload_start_z_m = 0;
};

// The energy account's running integrals since t = 0 (engine/energy_account.hpp), kept with the state so
// that a continued run carries them: for each integrated term of core/energy_terms.hpp, the energy it put
// into the particles (a loss: the energy it took out, positive); zero for the other terms.
struct EnergyFlows {
  double initial_J = 0;  // stored energy at t = 0 (the cell at rest)
  EnergyValues integral{};
};

struct State {
  FluidParticles fluid;
  WallParticles wall;
  Plates plates;
  PeriodicBox box;  // a periodic tissue's lateral period (model.md §10b); none for a cell or a cluster
  std::vector<double> start_volume_ratio;  // per cell: sum(m/rho) / enclosed volume when compression started
  // Per cell, a closed cell's fluid mass M_f (fluid.model = cavity: engine/cavity_fluid.hpp); empty for SPH.
  std::vector<double> cavity_mass_kg;
  std::vector<char> lamella_intact;  // per middle-lamella bond of a tissue: 1 until it separates (model.md §10)
  std::vector<double> lamella_peak_opening_m;  // per bond: its largest opening r - l0 so far (its damage)
  std::vector<double> bond_plastic_elongation_m;  // per wall bond: its plastic slider's elongation (wall_plasticity.hpp)
  Stage stage = Stage::Drying;
  std::int64_t step = 0;          // steps done in the whole run
  std::int64_t stage_step = 0;    // steps done in the current stage
  double time_s = 0;
  double smoothing_length_m = 0;  // h, Eq 6
  double initial_fluid_mass_kg = 0;   // M_f0: fluid mass at the start of drying (after the settle)
  double reference_diameter_m = 0;    // D0 of Eq 6: equivalent diameter of the wall at the start
  EnergyFlows energy;
  // Diagnostics of the last force evaluation (recorded, not state to integrate).
  double wall_tension_N_m = 0;    // mean membrane tension: sum(tension x length) / (2 area)
  double wall_pressure_Pa = 0;    // outward LJ push on the wall along its normals / area
  double lateral_stress_x_Pa = 0, lateral_stress_y_Pa = 0;  // a periodic slab's, tension positive (model.md §10b)
  // The last quasi-static relaxation's (engine/quasi_static.hpp): its largest force on a wall particle over
  // the pressure load, and its force evaluations; NaN in a dynamic run.
  double relaxation_residual = std::numeric_limits<double>::quiet_NaN();
  double relaxation_evaluations = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace cellsim
