#include "io/case_schema.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

namespace cellsim {
namespace {

constexpr double kMicro = 1e-6;

ParamSpec real(std::string key, std::string unit, double to_si, double Params::*member,
               double def, double min, bool min_incl, double max, bool max_incl,
               std::string meaning, std::string equation) {
  return {std::move(key), std::move(unit), to_si, member, def, min, max, min_incl, max_incl,
          std::move(meaning), std::move(equation), "", {}};
}

ParamSpec integer(std::string key, std::int64_t Params::*member, double def, double min, double max,
                  std::string meaning, std::string equation) {
  return {std::move(key), "1", 1.0, member, def, min, max, true, true,
          std::move(meaning), std::move(equation), "", {}};
}

ParamSpec derived(std::string key, std::string unit, double to_si, std::optional<double> Params::*member,
                  double min, bool min_incl, double max, bool max_incl,
                  std::string meaning, std::string equation, std::string auto_rule) {
  return {std::move(key), std::move(unit), to_si, member, std::nullopt, min, max, min_incl, max_incl,
          std::move(meaning), std::move(equation), std::move(auto_rule), {}};
}

ParamSpec derived_integer(std::string key, std::optional<std::int64_t> Params::*member, double min, double max,
                          std::string meaning, std::string equation, std::string auto_rule) {
  return {std::move(key), "1", 1.0, member, std::nullopt, min, max, true, true,
          std::move(meaning), std::move(equation), std::move(auto_rule), {}};
}

ParamSpec choice(std::string key, Choice Params::*member, std::vector<std::string> names, std::string meaning,
                 std::string equation) {
  const double last = static_cast<double>(names.size()) - 1;
  return {std::move(key), "-", 1.0, member, 0.0, 0, last, true, true,
          std::move(meaning), std::move(equation), "", std::move(names)};
}

std::vector<ParamSpec> build_specs() {
  using P = Params;
  return {
      // cell
      real("cell.diameter_um", "um", kMicro, &P::diameter_m, 150, 1, true, 10000, true,
           "initial cell diameter D0 = 2R (Table 3: R = 75 um)", "model.md §1, Eq 6"),
      integer("cell.n_wall", &P::n_wall, 2067, 12, 200000,
              "number of wall particles N_w (200 um cell: 2516)", "model.md §1"),
      integer("cell.n_fluid", &P::n_fluid, 3082, 1, 1000000,
              "number of fluid particles N_f (200 um cell: 3708)", "model.md §1, Eq 11"),
      real("cell.turgor_kPa", "kPa", 1e3, &P::turgor_Pa, 200, 0, true, 10000, true,
           "fresh turgor pressure P_T0; P_T(X) = P_T0 X", "Eq 7, model.md §5"),
      real("cell.fluid_density_kg_m3", "kg/m^3", 1.0, &P::fluid_density_kg_m3, 1000, 0, false, 1e5, true,
           "reference fluid density rho0; fluid mass m_f = rho0 (4/3) pi R^3 / N_f", "Eq 7, model.md §1"),
      real("cell.wall_mass_fraction", "1", 1.0, &P::wall_mass_fraction, 0.1, 0, false, 10, true,
           "total wall mass / total fluid mass (Table 3: 1.767e-10 / 1.767e-9)", "model.md §1"),
      derived("cell.fill_gap_um", "um", kMicro, &P::fill_gap_m, 0, true, 1000, true,
              "fluid particles fill the sphere of radius R - fill_gap", "model.md §1",
              "0.7 r0 (lennard_jones), half the fluid spacing (pressure)"),
      // tissue: cells side by side (1 x 1 x 1: the single cell)
      integer("tissue.cells_x", &P::cells_x, 1, 1, 20, "cells along x", "model.md §10"),
      integer("tissue.cells_y", &P::cells_y, 1, 1, 20, "cells along y", "model.md §10"),
      integer("tissue.cells_z", &P::cells_z, 1, 1, 20, "cells along z (layers, stacked between the plates)",
              "model.md §10"),
      choice("tissue.packing", &P::packing, {"cubic", "close"},
             "where the cells' centres sit: cubic (a simple cubic lattice) or close (hexagonal layers stacked "
             "ABC, face-centred cubic)", "model.md §10"),
      choice("tissue.lateral", &P::lateral, {"free", "periodic"},
             "the sides of the tissue: free (a cluster of cells_x x cells_y x cells_z), or a slab periodic in x and y "
             "(cells_x x cells_y cells to a period) whose period follows zero lateral stress in drying "
             "(compression.lateral says what it does under the plates)", "model.md §10b"),
      real("tissue.period_viscosity_Pa_s", "Pa s", 1.0, &P::period_viscosity_Pa_s, 5, 0, false, 1e6, true,
           "a periodic slab's period strains at -(its lateral stress) / this while it follows zero lateral stress "
           "(5 Pa s: 100 kPa strains it 0.02 per us; the explicit step is stable while this exceeds half the "
           "cells' lateral stiffness times dt, ~0.85 Pa s for a fresh slab at dt 1 ns and more as it dries); the "
           "quasi-static scheme does not read it: its period is at zero lateral stress at every step",
           "model.md §10b"),
      real("tissue.centre_distance_over_diameter", "1", 1.0, &P::centre_distance_over_diameter, 0.85, 0.6, true, 2,
           true, "distance between neighbouring cells' centres / D0; below 1 the cells press flat faces on each "
           "other (0.85: porosity ~0.23 in cubic packing)", "model.md §10"),
      real("tissue.diameter_spread", "1", 1.0, &P::diameter_spread, 0, 0, true, 0.3, true,
           "standard deviation of the cells' diameters / D0 (seeded; faces follow the radical planes)",
           "model.md §10"),
      integer("tissue.seed", &P::tissue_seed, 1, 0, 2147483647, "seed of the diameters' spread", "model.md §10"),
      derived("tissue.wall_gap_um", "um", kMicro, &P::wall_gap_m, 0, false, 1000, true,
              "distance between the particle layers of facing walls (each layer is its wall's mid-surface)",
              "model.md §10", "the wall thickness t0 (two half walls)"),
      real("tissue.contact_stiffness_N_m", "N/m", 1.0, &P::contact_stiffness_N_m, 1e3, 0, true, 1e9, true,
           "repulsion between wall particles of different cells closer than the wall gap (Eq 22's form and k_pw)",
           "model.md §10"),
      real("tissue.lamella_stiffness_N_m", "N/m", 1.0, &P::lamella_stiffness_N_m, 1e3, 0, true, 1e9, true,
           "elastic stiffness of a middle-lamella bond between facing wall particles, about its initial length "
           "(up to its peak tension)", "model.md §10"),
      real("tissue.lamella_strength_MPa", "MPa", 1e6, &P::lamella_strength_Pa, 1.5, 0, true, 1e4, true,
           "a middle-lamella bond's peak tension is this times the area a wall particle owns (pi D0^2 / N_w: "
           "51 uN for the default cell); past it the bond softens", "model.md §10"),
      real("tissue.lamella_fracture_energy_J_m2", "J/m^2", 1.0, &P::lamella_fracture_energy_J_m2, 5.0, 0, true, 1e6,
           true,
           "energy that separates a middle-lamella bond for good, per area a wall particle owns: the bond softens "
           "linearly from its peak to zero force over this (0: brittle, it breaks at its peak)",
           "model.md §10"),
      // fluid
      choice("fluid.model", &P::fluid_model, {"sph", "cavity"},
             "the cell fluid: sph (particles, the paper's) or cavity (a closed cell of one uniform pressure, P from "
             "Eq 7 at its mass / the enclosed volume, pushing on the wall as P dV/dx; no particles: the SPH-only keys "
             "are ignored, with a warning)", "docs/model.md §11, engine/cavity_fluid.hpp"),
      real("fluid.viscosity_Pa_s", "Pa s", 1.0, &P::viscosity_Pa_s, 0.1, 0, true, 1e4, true,
           "dynamic viscosity mu", "Eq 4"),
      real("fluid.bulk_modulus_MPa", "MPa", 1e6, &P::bulk_modulus_Pa, 20, 0, false, 1e5, true,
           "fluid compression modulus K", "Eq 7"),
      real("fluid.eos_exponent", "1", 1.0, &P::eos_exponent, 7, 1, true, 15, true,
           "exponent of the Tait equation of state", "Eq 7"),
      real("fluid.density_diffusion", "1", 1.0, &P::density_diffusion, 0, 0, true, 1, true,
           "delta of the delta-SPH density diffusion, d(rho_i)/dt += delta h c0 sum_j V_j psi_ij . grad W (ours, not "
           "the paper's; 0: off; 0.1 is the usual value, Antuono et al. 2010)", "sph_terms.hpp, docs/model.md §2"),
      derived("fluid.h0_um", "um", kMicro, &P::h0_m, 0, false, 1000, true,
              "initial SPH smoothing length h0 (set this or fluid.h_over_dx; both only if they agree, as a "
              "resolved case has them)",
              "Eq 5, Eq 6",
              "fluid.h_over_dx x dx (dx: the fluid lattice spacing)"),
      derived("fluid.h_over_dx", "1", 1.0, &P::h_over_dx, 0.5, true, 3, true,
              "smoothing ratio h0 / dx: (4/3) pi (2 h/dx)^3 = 33.5 (h/dx)^3 neighbours within the support 2h, 23 "
              "at 0.888 and 58 at 1.2 (SPH practice for this kernel: 1.2-1.3); a resolution study keeps it fixed", "Eq 5, Eq 6",
              "6.8 um / dx_ref = 0.888, dx_ref the fluid spacing of the default 150 um cell (the paper's h0 there)"),
      // wall
      real("wall.G_MPa", "MPa", 1e6, &P::G_Pa, 18, 0, true, 1e5, true,
           "cell wall shear modulus G", "Eq 15"),
      real("wall.thickness_um", "um", kMicro, &P::thickness_m, 6, 0, true, 1000, true,
           "cell wall thickness t0", "Eq 15"),
      real("wall.damping_N_s_m", "N s/m", 1.0, &P::damping_N_s_m, 5e-6, 0, true, 1, true,
           "wall bond damping constant gamma", "Eq 16"),
      real("wall.bending_stiffness_J", "J", 1.0, &P::bending_stiffness_J, 1e-10, 0, true, 1e-3, true,
           "wall bending stiffness k_b", "Eq 20"),
      real("wall.contraction_stiffness_N_m", "N/m", 1.0, &P::contraction_stiffness_N_m, 1e4, 0, true, 1e9, true,
           "wall contraction force coefficient k_wc", "Eq 21"),
      real("wall.contraction_ratio", "1", 1.0, &P::contraction_ratio, 0.4, 0, true, 1, false,
           "c = a/b: fully dried rest length is l0 (1 - c)", "Eq 21"),
      derived("wall.yield_stress_MPa", "MPa", 1e6, &P::yield_stress_Pa, 0, false, 1e5, true,
              "the elastic-plastic wall (ours): a bond whose tension reaches this flow stress over the wall section "
              "it carries, t0 l0 / sqrt 3, lengthens a plastic slider in series with its springs (tension only; "
              "the set stays)",
              "docs/model.md §3b, wall_plasticity.hpp", "none: the paper's elastic wall"),
      real("wall.hardening_MPa", "MPa", 1e6, &P::hardening_Pa, 0, 0, true, 1e6, true,
           "the elastic-plastic wall's linear hardening: the flow stress grows by this x the plastic strain "
           "delta_p / l0 (0: perfectly plastic; unused without wall.yield_stress_MPa)",
           "docs/model.md §3b, wall_plasticity.hpp"),
      // heterogeneity (ours): seeded lognormal factors of mean 1
      integer("heterogeneity.seed", &P::heterogeneity_seed, 1, 0, 2147483647,
              "seed of the heterogeneous properties' draws (the same seed gives the same bits)",
              "docs/model.md §3c, heterogeneity.hpp"),
      real("heterogeneity.wall_G_cv", "1", 1.0, &P::G_cv, 0, 0, true, 3, true,
           "coefficient of variation of each wall bond's shear modulus G (lognormal, mean G; 0: uniform)",
           "docs/model.md §3c, Eq 15"),
      real("heterogeneity.wall_thickness_cv", "1", 1.0, &P::thickness_cv, 0, 0, true, 3, true,
           "coefficient of variation of each wall bond's thickness t0 (lognormal, mean t0; Eq 15's G t0 and the "
           "plastic wall's section; 0: uniform)", "docs/model.md §3c, Eq 15"),
      real("heterogeneity.fluid_viscosity_cv", "1", 1.0, &P::viscosity_cv, 0, 0, true, 3, true,
           "coefficient of variation of each cell's fluid viscosity mu (lognormal, mean mu; 0: uniform)",
           "docs/model.md §3c, Eq 4"),
      real("heterogeneity.correlation_length_um", "um", kMicro, &P::correlation_length_m, 0, 0, true, 1e4, true,
           "length over which the wall's factors are correlated (a Gaussian-smoothed white noise over each cell's "
           "wall; 0: each bond its own draw)", "docs/model.md §3c"),
      // coupling
      choice("coupling.model", &P::coupling_model, {"lennard_jones", "pressure"},
             "wall-fluid coupling: lennard_jones (the paper's, Eqs 12-13, 17-19) or pressure (the fluid's SPH "
             "pressure on the wall's surface, with the exact reaction; docs/model-closures.md)",
             "model.md §4"),
      derived("coupling.r0_um", "um", kMicro, &P::r0_m, 0, false, 1000, true,
              "wall-fluid Lennard-Jones equilibrium gap r0", "Eqs 12-13, 17-19",
              "1.8 x the largest wall-triangle circumradius (8.1 um for the default mesh)"),
      real("coupling.repulsion_f0_N_m", "N m", 1.0, &P::repulsion_f0_N_m, 5e-12, 0, true, 1, true,
           "LJ contact strength for r < r0 (Table 3 prints N/m; N m gives a force)", "Eqs 12, 17-18"),
      real("coupling.attraction_f0_N_m", "N m", 1.0, &P::attraction_f0_N_m, 1e-11, 0, true, 1, true,
           "LJ contact strength for r0 <= r < r_c", "Eqs 13, 19"),
      real("coupling.attraction_cutoff_over_h", "1", 1.0, &P::attraction_cutoff_over_h, 2, 0, true, 2, true,
           "attraction cut-off r_c in units of the smoothing length h", "Eqs 13, 19"),
      real("coupling.backstop_range_over_dx", "1", 1.0, &P::backstop_range_over_dx, 0.25, 0, true, 1, true,
           "pressure coupling only: a fluid particle closer than this x dx (the fluid spacing, following h) to a wall "
           "element's tangent plane is pushed back by K (1 - d/d_b)^2 in place of its pressure (0: no backstop)",
           "docs/model.md §4"),
      // settle: the start at rest
      integer("settle.max_iterations", &P::settle_max_iterations, 20000, 0, 1e9,
              "pseudo-steps of the relaxation at rest at the fresh turgor before drying starts (0: start "
              "from the cut lattice as built, with its shock)", "docs/model-closures.md"),
      real("settle.tolerance", "1", 1.0, &P::settle_tolerance, 3e-4, 0, false, 1, true,
           "the relaxation stops when the largest fluid acceleration is below this fraction of "
           "P_T0 / (rho0 dx)", "docs/model-closures.md"),
      // drying
      real("drying.dryness", "1", 1.0, &P::dryness, 1.0, 0, false, 1, true,
           "normalised moisture content X/X0 (1: fresh)", "Eq 21, model.md §5"),
      derived_integer("drying.steps", &P::drying_steps, 0, 1e9,
                      "most time steps of the drying stage: it ends earlier, at steady state (a case that reaches "
                      "the cap without it says so)", "model.md §5",
                      "80 us / time.dt_ns (80000 at 1 ns): a cap in time, whatever the time step"),
      real("drying.Lp_m_per_s_Pa", "m/(s Pa)", 1.0, &P::drying_Lp_m_per_s_Pa, 2.5e-6, 0, true, 1, true,
           "wall permeability L_p during drying (raised to reach steady state fast)", "Eq 11"),
      real("drying.ramp_time_us", "us", kMicro, &P::ramp_time_s, 20, 0, true, 1e6, true,
           "time over which L_ref and the turgor ramp (smoothstep) from their fresh values to those of X", "Eq 21, model.md §5"),
      real("drying.steady_window_us", "us", kMicro, &P::steady_window_s, 5, 0, false, 1e6, true,
           "steady state: the criteria below must hold over this window, after the ramp", "model.md §5"),
      real("drying.steady_pressure_tolerance", "1", 1.0, &P::steady_pressure_tolerance, 0.005, 0, false, 1, true,
           "steady state: |mean fluid pressure - P_T(X)| at most this fraction of P_T0", "model.md §5"),
      real("drying.steady_volume_tolerance", "1", 1.0, &P::steady_volume_tolerance, 5e-4, 0, false, 1, true,
           "steady state: (largest - smallest enclosed volume) / volume over the window at most this",
           "model.md §5"),
      derived("drying.steady_rms_speed_m_s", "m/s", 1.0, &P::steady_rms_speed_m_s, 0, false, 1000, true,
              "steady state: rms fluid speed sqrt(2 KE / M) at most this", "model.md §5",
              "0.02 (lennard_jones), 0.05 (pressure): a fluid at rest jitters at ~0.01 and ~0.03 m/s rms"),
      real("drying.pressure_closure_time_us", "us", kMicro, &P::pressure_closure_time_s, 2, 0, true, 1e6, true,
           "relaxation time of the wall-pressure closure during drying (0: off)", "docs/model-closures.md"),
      // compression
      derived_integer("compression.steps", &P::compression_steps, 0, 1e9,
                      "maximum time steps of the compression stage", "model.md §6",
                      "25 us / time.dt_ns (25000 at 1 ns), x 1 m/s / plate speed for slower plates: a cap in time and travel"),
      real("compression.plate_speed_m_s", "m/s", 1.0, &P::plate_speed_m_s, 1, 0, false, 1000, true,
           "downward speed of the top plate", "model.md §6"),
      real("compression.Lp_m_per_s_Pa", "m/(s Pa)", 1.0, &P::compression_Lp_m_per_s_Pa, 1e-12, 0, true, 1, true,
           "wall permeability L_p during compression", "Eq 11"),
      real("compression.gap_um", "um", kMicro, &P::plate_gap_m, 2, 0, true, 1000, true,
           "initial gap between the top plate's reach and the cell", "model.md §6"),
      real("compression.plate_range_um", "um", kMicro, &P::plate_range_m, 3, 0, false, 100, true,
           "plate-wall interaction range r_pw", "Eq 22"),
      real("compression.plate_stiffness_N_m", "N/m", 1.0, &P::plate_stiffness_N_m, 1e3, 0, false, 1e9, true,
           "plate-wall force coefficient k_pw", "Eq 22"),
      real("compression.plate_length_um", "um", kMicro, &P::plate_length_m, 150, 0, false, 1e5, true,
           "plate footprint along x (the plate stress divides by length x width); a periodic slab's plates "
           "cover every period, and its stress divides by the period's area", "Eq 22, model.md §8, §10b"),
      real("compression.plate_width_um", "um", kMicro, &P::plate_width_m, 150, 0, false, 1e5, true,
           "plate footprint along y (not used by a periodic slab)", "Eq 22, model.md §8, §10b"),
      choice("compression.lateral", &P::compression_lateral, {"confined", "unconfined"},
             "what a periodic slab's period does under the plates: held (confined, as a sample in a die) or "
             "following zero lateral stress (unconfined); a cell or a cluster takes only confined, the default",
             "model.md §10b"),
      choice("compression.cell_rotation", &P::cell_rotation, {"auto", "held", "free"},
             "a quasi-static lone cell's rigid rotation: held at zero (Eckart's condition on the wall's positions "
             "when the compression starts, a constraint that does no work), or free, when a sequence of equilibria "
             "rolls the cell between the frictionless plates to its softest orientation (a dynamic cell's inertia "
             "holds it over a compression; a tissue's neighbours hold its cells); auto: held for a lone cell in the "
             "quasi_static scheme, free otherwise", "docs/model-closures.md, engine/rotation_hold.hpp"),
      derived("compression.end_strain", "1", 1.0, &P::end_strain, 0, false, 1, false,
              "stop compression when the nominal strain reaches this value", "model.md §6",
              "none: run all compression.steps"),
      derived("compression.unload_at_strain", "1", 1.0, &P::unload_at_strain, 0, false, 1, false,
              "load-unload: at this nominal strain the top plate turns and moves back up at "
              "compression.unload_speed_m_s; the stage ends when the cell leaves the top plate (its strain then is "
              "the permanent set)", "docs/model.md §6", "none: the plate only loads"),
      derived("compression.unload_speed_m_s", "m/s", 1.0, &P::unload_speed_m_s, 0, false, 1000, true,
              "upward speed of the top plate while it unloads", "docs/model.md §6",
              "compression.plate_speed_m_s"),
      derived("compression.volume_closure_time_us", "us", kMicro, &P::volume_closure_time_s, 0, true, 1e6, true,
              "relaxation time over which a closed cell's fluid volume sum(m/rho) is held to the volume its wall "
              "encloses during compression, at their ratio when it started (0: off)", "docs/model-closures.md",
              "1 (pressure), 0 (lennard_jones)"),
      // time
      real("time.dt_ns", "ns", 1e-9, &P::dt_s, 1, 0, false, 1000, true,
           "time step (checked against the wall-spring limit at the start, the CFL limits every step)", "model.md §7"),
      choice("time.density_update", &P::density_update, {"auto", "kick", "drift"},
             "when the leapfrog advances the fluid's density and mass: kick (with the velocity, in both half kicks: "
             "one pass over the pairs a step), drift (with the positions, from the half-step velocities: two passes, "
             "stable where kick lets the acoustic modes grow); auto: kick for lennard_jones, drift for pressure",
             "docs/model.md §7"),
      choice("time.scheme", &P::time_scheme, {"dynamic", "quasi_static"},
             "dynamic: the leapfrog of time.dt_ns; quasi_static (fluid.model = cavity only): each step of time.dt_ns "
             "moves the plates and the drying ramp and integrates Eq 11 over it, then relaxes the wall to "
             "equilibrium", "docs/model.md §11, engine/quasi_static.hpp"),
      real("time.equilibrium_tolerance", "1", 1.0, &P::equilibrium_tolerance, 1e-3, 0, false, 1, true,
           "a closed cell's relaxations (quasi_static steps, the settle, the volumetric modulus): one ends when the "
           "largest force on a wall particle is below this fraction of its pressure load, max(P_T0, |P|) x the mean "
           "area a wall particle owns",
           "engine/quasi_static.hpp"),
      integer("time.relaxation_max_iterations", &P::relaxation_max_iterations, 200000, 1, 1e9,
              "a closed cell's relaxations (quasi_static steps, the volumetric modulus): the force evaluations one may "
              "take; beyond, the run stops (exit 3)",
              "engine/quasi_static.hpp"),
      derived("time.min_increment_ns", "ns", 1e-9, &P::min_increment_s, 0, false, 1000, true,
              "quasi_static: the shortest increment a step may be cut to (below time.dt_ns a step's increment is "
              "cut to a quarter where its relaxation fails, snaps or moves the wall too far, and doubles after easy "
              "ones, back to time.dt_ns; records stay once a step). One value for every requested step gives the "
              "path one resolution at its snaps: at 1 m/s, 1 ns is 1 nm of plate travel",
              "engine/quasi_static.hpp, docs/model-closures.md", "time.dt_ns: every step one increment"),
      real("time.snap_loss_share", "1", 1.0, &P::snap_loss_share, 0.05, 0, false, 1e6, true,
           "quasi_static, adaptive increments: an increment whose relaxation releases more than this share of "
           "the loads' work over it (a snap) is cut",
           "engine/quasi_static.hpp"),
      choice("time.predictor", &P::increment_predictor, {"none", "secant"},
             "quasi_static: where an increment's relaxation starts. none: the last equilibrium with the wall that "
             "touches a plate moved with it; secant: the last increment's motion added, scaled to this increment, "
             "where that starts with a smaller largest force (and dropped where it does not)",
             "engine/quasi_static.hpp, docs/model-closures.md"),
      real("time.increment_move_over_spacing", "1", 1.0, &P::increment_move_over_spacing, 0.05, 0, true, 10, true,
           "quasi_static, adaptive increments: an increment whose relaxation moves a wall particle farther than "
           "this share of the wall's mean bond rest length is cut (a jump to another branch that releases little "
           "energy), and one grows only while its largest move is within half of it; 0: not used",
           "engine/quasi_static.hpp"),
      // output
      integer("output.record_every", &P::record_every, 100, 1, 1e9,
              "steps between time-series records", "model.md §8"),
      integer("output.snapshot_every", &P::snapshot_every, 5000, 0, 1e9,
              "steps between particle snapshots (0: first and last state only)", "output-reference.md"),
      real("output.progress_interval_s", "s", 1.0, &P::progress_interval_s, 5, 0, true, 1e6, true,
           "wall-clock seconds between progress lines on stderr (0: every step)", "README.md"),
  };
}

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

const std::vector<ParamSpec>& param_specs() {
  static const std::vector<ParamSpec> specs = build_specs();
  return specs;
}

const ParamSpec* find_param(const std::string& key) {
  for (const auto& s : param_specs())
    if (s.key == key) return &s;
  return nullptr;
}

bool is_integer(const ParamSpec& spec) {
  return std::holds_alternative<std::int64_t Params::*>(spec.member) ||
         std::holds_alternative<std::optional<std::int64_t> Params::*>(spec.member);
}

bool is_optional(const ParamSpec& spec) {
  return std::holds_alternative<std::optional<double> Params::*>(spec.member) ||
         std::holds_alternative<std::optional<std::int64_t> Params::*>(spec.member);
}

bool is_choice(const ParamSpec& spec) { return std::holds_alternative<Choice Params::*>(spec.member); }

std::string describe_range(const ParamSpec& spec) {
  if (is_choice(spec)) {
    std::string names;
    for (const auto& name : spec.choices) names += (names.empty() ? "" : ", ") + name;
    return "one of " + names;
  }
  std::string r;
  if (std::isfinite(spec.min)) r += format_number(spec.min) + (spec.min_inclusive ? " <= " : " < ");
  r += "value";
  if (std::isfinite(spec.max)) r += (spec.max_inclusive ? " <= " : " < ") + format_number(spec.max);
  if (is_integer(spec)) r += ", an integer";
  return r;
}

// The keys only one fluid model reads: SPH's particles, smoothing, viscosity, coupling, closures and CFL-bound
// settle (engine/sph_fluid.hpp); a closed cell's relaxations' (quasi_static.hpp, read in the settle, the
// quasi-static steps and the volumetric modulus, whichever the time scheme). The keys only one scheme reads:
// the quasi-static one's rotation hold (a dynamic cell's inertia holds its rotation); the dynamic one's
// period follower (quasi-static, a periodic slab's period is part of each equilibrium).
const std::vector<KeysReadOnlyBy>& keys_read_only_by() {
  static const std::vector<KeysReadOnlyBy> keys = {
      {"fluid.model", "sph",
       {"cell.n_fluid", "cell.fill_gap_um", "fluid.viscosity_Pa_s", "fluid.density_diffusion", "fluid.h0_um",
        "fluid.h_over_dx", "heterogeneity.fluid_viscosity_cv", "coupling.model", "coupling.r0_um",
        "coupling.repulsion_f0_N_m", "coupling.attraction_f0_N_m", "coupling.attraction_cutoff_over_h",
        "coupling.backstop_range_over_dx", "settle.tolerance", "drying.steady_rms_speed_m_s",
        "drying.pressure_closure_time_us", "compression.volume_closure_time_us", "time.density_update"}},
      {"fluid.model", "cavity", {"time.equilibrium_tolerance", "time.relaxation_max_iterations"}},
      {"time.scheme", "quasi_static",
       {"compression.cell_rotation", "time.min_increment_ns", "time.snap_loss_share",
        "time.increment_move_over_spacing", "time.predictor"}},
      {"time.scheme", "dynamic", {"tissue.period_viscosity_Pa_s"}},
  };
  return keys;
}

std::string read_only_by(const std::string& key) {
  for (const KeysReadOnlyBy& own : keys_read_only_by())
    if (std::find(own.keys.begin(), own.keys.end(), key) != own.keys.end()) return own.reader();
  return "";
}

std::string reference_markdown() {
  std::ostringstream s;
  s << "| key | unit | default | allowed | meaning | equation | read only by |\n"
       "|---|---|---|---|---|---|---|\n";
  for (const auto& p : param_specs()) {
    const std::string def = is_choice(p)        ? p.choices.front()
                            : p.default_value ? format_number(*p.default_value)
                                              : "auto: " + p.auto_rule;
    const std::string reader = read_only_by(p.key);
    s << "| `" << p.key << "` | " << p.unit << " | " << def << " | " << describe_range(p) << " | "
      << p.meaning << " | " << p.equation << " | " << (reader.empty() ? "" : "`" + reader + "`") << " |\n";
  }
  return s.str();
}

}  // namespace cellsim

namespace cellsim {

std::string json_schema() {
  using nlohmann::json;
  std::map<std::string, json> sections;
  for (const auto& p : param_specs()) {
    const std::string section = p.key.substr(0, p.key.find('.'));
    json rule = {{"description", p.meaning + " [" + p.unit + "] (" + p.equation + ")"}};
    // "default" (an annotation, not a rule): the value an absent key takes; derived keys have none.
    if (is_choice(p)) {
      rule["type"] = "string";
      rule["enum"] = p.choices;
      rule["default"] = p.choices.front();
    } else {
      const json number = is_integer(p) ? json("integer") : json("number");
      rule["type"] = is_optional(p) ? json({number, "null"}) : number;
      rule[p.min_inclusive ? "minimum" : "exclusiveMinimum"] = p.min;
      rule[p.max_inclusive ? "maximum" : "exclusiveMaximum"] = p.max;
      if (p.default_value)
        rule["default"] = is_integer(p) ? json(static_cast<long long>(*p.default_value)) : json(*p.default_value);
    }
    json& s = sections[section];
    if (s.is_null()) s = {{"type", "object"}, {"additionalProperties", false}, {"properties", json::object()}};
    s["properties"][p.key.substr(p.key.find('.') + 1)] = rule;
  }
  json schema = {{"$schema", "http://json-schema.org/draft-07/schema#"},
                 {"title", "cellsim case"},
                 {"description", "Generated by 'cellsim schema'; see docs/case-reference.md"},
                 {"type", "object"},
                 {"additionalProperties", false},
                 {"properties", {{"description", {{"type", "string"}}}}}};
  for (auto& [name, s] : sections) schema["properties"][name] = s;
  return schema.dump(2) + "\n";
}

}  // namespace cellsim
