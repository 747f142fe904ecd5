#pragma once
// Every parameter of a case, in SI units, after reading and resolving the JSON case file.
// The JSON keys (human units, e.g. wall.G_MPa) map onto these members in case_schema.cpp.
#include <cstdint>
#include <optional>

namespace cellsim {

using Choice = int;  // the index of a choice key's name (case_schema.cpp lists the names)

// coupling.model (model.md §4): how the wall and the fluid push on each other.
enum CouplingModel : Choice { kLennardJones = 0, kPressure = 1 };

// fluid.model (model.md §11): the cell fluid as SPH particles (the paper's), or as a closed cell of one
// uniform pressure (engine/cavity_fluid.hpp), the quasi-static reference.
enum FluidModelChoice : Choice { kSphFluid = 0, kCavityFluid = 1 };

// time.scheme: the leapfrog in time (dynamic), or each increment of time a wall at equilibrium
// (quasi_static: engine/quasi_static.hpp; a cavity fluid only).
enum TimeScheme : Choice { kDynamic = 0, kQuasiStatic = 1 };

// time.density_update (docs/model.md §7): when the leapfrog advances the density (and mass) of the
// fluid. auto: kick for lennard_jones (the paper's study as before), drift for pressure.
enum DensityUpdate : Choice { kDensityAuto = 0, kDensityKick = 1, kDensityDrift = 2 };

// tissue.packing (model.md §10): where the cells' centres sit.
enum Packing : Choice { kCubicPacking = 0, kClosePacking = 1 };

// tissue.lateral (model.md §10b): a cluster with free sides, or a slab periodic in x and y whose period
// follows zero lateral stress in drying.
enum LateralBoundary : Choice { kLateralFree = 0, kLateralPeriodic = 1 };

// compression.lateral (model.md §10b): under the plates a periodic slab's period is held (confined) or
// keeps following zero lateral stress (unconfined). A separate key from tissue.lateral because the
// drying does not depend on it: confined and unconfined compressions continue one dried state.
enum LateralInCompression : Choice { kLateralConfined = 0, kLateralUnconfined = 1 };

// compression.cell_rotation (engine/rotation_hold.hpp): a quasi-static lone cell's rigid rotation held at
// zero (held) or left to the frictionless plates (free); auto resolves to held for a lone cell in the
// quasi-static scheme and to free otherwise.
enum CellRotation : Choice { kRotationAuto = 0, kRotationHeld = 1, kRotationFree = 2 };
// time.predictor (quasi-static): where an increment's relaxation starts.
enum IncrementPredictor : Choice { kPredictorNone = 0, kPredictorSecant = 1 };

struct Params {
  // cell geometry and particles (model.md §1)
  double diameter_m = 0;                // D0 = 2R
  std::int64_t n_wall = 0;              // N_w
  std::int64_t n_fluid = 0;             // N_f
  double turgor_Pa = 0;                 // fresh turgor P_T0 (Table 3)
  double fluid_density_kg_m3 = 0;       // rho0
  double wall_mass_fraction = 0;        // wall mass / fluid mass (Table 3: 0.1)
  std::optional<double> fill_gap_m;     // fluid fill radius is R - fill_gap (auto: 0.7 r0, or dx/2 for the pressure coupling)

  // tissue of cells (model.md §10); 1 x 1 x 1 is the single cell of the paper
  std::int64_t cells_x = 1, cells_y = 1, cells_z = 1;  // cells along each axis (layers along z)
  Choice packing = kCubicPacking;
  Choice lateral = kLateralFree;
  Choice compression_lateral = kLateralConfined;  // compression.lateral, for a periodic slab
  Choice cell_rotation = kRotationAuto;           // compression.cell_rotation (quasi-static)
  double period_viscosity_Pa_s = 0;     // the period strains at -(lateral stress) / this while it follows
  double centre_distance_over_diameter = 0;  // centre distance of touching neighbours / D0
  double diameter_spread = 0;           // standard deviation of the cells' diameters / D0
  std::int64_t tissue_seed = 0;         // of the diameters' spread
  std::optional<double> wall_gap_m;     // between facing walls' particle layers (auto: t0)
  double contact_stiffness_N_m = 0;     // wall-wall repulsion between cells, Eq 22's form
  double lamella_stiffness_N_m = 0;     // middle-lamella bond spring
  double lamella_strength_Pa = 0;       // a bond's peak tension is this x a wall particle's area
  double lamella_fracture_energy_J_m2 = 0;  // energy to separate a bond, per wall area it owns

  // heterogeneous properties (geometry/heterogeneity.hpp): coefficients of variation, 0 for uniform
  std::int64_t heterogeneity_seed = 1;
  double G_cv = 0, thickness_cv = 0;    // per wall bond
  double viscosity_cv = 0;              // per cell
  double correlation_length_m = 0;      // of the wall's factors (0: each bond its own draw)

  // fluid, Table 1
  Choice fluid_model = kSphFluid;
  double viscosity_Pa_s = 0;            // mu, Eq 4
  double bulk_modulus_Pa = 0;           // K, Eq 7
  double eos_exponent = 0;              // 7 in Eq 7
  double density_diffusion = 0;         // delta of delta-SPH (ours; 0: off, as in the paper)
  std::optional<double> h0_m;           // initial smoothing length, Eq 6 (auto: h_over_dx * dx)
  std::optional<double> h_over_dx;      // smoothing ratio h0 / dx (auto: 6.8 um / dx_ref, the paper's 0.888)

  // wall, Table 2
  double G_Pa = 0;                      // shear modulus, Eq 15
  double thickness_m = 0;               // t0, Eq 15
  double damping_N_s_m = 0;             // gamma, Eq 16
  double bending_stiffness_J = 0;       // k_b, Eq 20
  double contraction_stiffness_N_m = 0; // k_wc, Eq 21
  double contraction_ratio = 0;         // c = a/b, Eq 21
  std::optional<double> yield_stress_Pa;  // the elastic-plastic wall's sigma_y (none: elastic; wall_plasticity.hpp)
  double hardening_Pa = 0;              // its hardening modulus H

  // wall-fluid coupling: the paper's Lennard-Jones (Eqs 12-13, 17-19) or the fluid's pressure (model.md §4)
  Choice coupling_model = kLennardJones;
  std::optional<double> r0_m;           // LJ equilibrium gap (auto: 1.8 x largest triangle circumradius)
  double repulsion_f0_N_m = 0;          // f0 for r < r0
  double attraction_f0_N_m = 0;         // f0 for r0 <= r < r_c
  double attraction_cutoff_over_h = 0;  // r_c / h
  double backstop_range_over_dx = 0;    // the pressure coupling's backstop range d_b / dx (0: none)

  // the start at rest (settle.hpp)
  std::int64_t settle_max_iterations = 0;  // 0: start from the cell as built
  double settle_tolerance = 0;          // largest fluid acceleration / (P_T0 / (rho0 dx)) to stop at

  // drying stage, model.md §5
  double dryness = 0;                   // X/X0
  std::optional<std::int64_t> drying_steps;  // the cap: drying ends earlier at steady state (auto: stage_caps.hpp)
  double steady_window_s = 0;           // steady_state.hpp: the window the criterion holds over
  double steady_pressure_tolerance = 0; // |P_mean - P_T(X)| / P_T0
  double steady_volume_tolerance = 0;   // (V_max - V_min) / V over the window
  std::optional<double> steady_rms_speed_m_s;  // sqrt(2 KE_fluid / M_fluid) (auto: by coupling, steady_state.hpp)
  double drying_Lp_m_per_s_Pa = 0;      // L_p, Eq 11
  double ramp_time_s = 0;               // smoothstep ramp of L_ref, model.md §5
  double pressure_closure_time_s = 0;   // relaxation time of the wall-pressure closure (0: off)

  // compression stage, model.md §6 and Eq 22
  std::optional<std::int64_t> compression_steps;  // the cap (auto: stage_caps.hpp)
  double plate_speed_m_s = 0;
  double compression_Lp_m_per_s_Pa = 0;
  double plate_gap_m = 0;               // initial gap of the top plate above the cell
  double plate_range_m = 0;             // r_pw, Eq 22
  double plate_stiffness_N_m = 0;       // k_pw, Eq 22
  double plate_length_m = 0;            // footprint in x
  double plate_width_m = 0;             // footprint in y
  std::optional<double> end_strain;     // stop compression at this nominal strain
  std::optional<double> unload_at_strain;  // load-unload: the top plate turns back at this nominal strain
  std::optional<double> unload_speed_m_s;  // its upward speed (auto: plate_speed_m_s)
  std::optional<double> volume_closure_time_s;  // relaxation time of the volume closure (0: off; auto: by coupling)

  // time integration, model.md §7
  double dt_s = 0;
  Choice density_update = kDensityAuto;
  Choice time_scheme = kDynamic;
  double equilibrium_tolerance = 0;     // quasi_static: largest wall force / its pressure load to stop at
  std::int64_t relaxation_max_iterations = 0;  // quasi_static: the cap of one relaxation
  std::optional<double> min_increment_s;  // quasi_static: the least increment (auto: dt, every step one increment)
  double snap_loss_share = 0;           // quasi_static, adaptive: the relaxation loss / loads' work that cuts
  Choice increment_predictor = kPredictorNone;  // time.predictor (quasi_static)
  double increment_move_over_spacing = 0;  // quasi_static, adaptive: a relaxation's largest move / mean l0 that cuts (0: off)

  // output
  std::int64_t record_every = 0;        // steps between time-series records
  std::int64_t snapshot_every = 0;      // steps between particle snapshots (0: first and last only)
  double progress_interval_s = 0;       // wall-clock seconds between progress lines on stderr
};

}  // namespace cellsim
