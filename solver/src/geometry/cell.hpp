#pragma once
// The initial cell (model.md §1): wall particles and mesh, fluid particles, masses.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include "core/params.hpp"
#include "geometry/wall_mesh.hpp"

namespace cellsim {

struct Cell {
  Eigen::Matrix3Xd wall_x;      // wall particle positions [m], sphere of radius R
  WallMesh mesh;
  Eigen::Matrix3Xd fluid_x;     // fluid particle positions [m], inside R - fill_gap
  double fluid_mass_kg = 0;     // per fluid particle: rho0 (4/3) pi R^3 / N_f
  double wall_mass_kg = 0;      // per wall particle: fraction x rho0 (4/3) pi R^3 / N_w
  double fluid_spacing_m = 0;   // cubic lattice spacing dx
};

// Builds the cell and fills in the derived parameters of p that are still unset
// (coupling.r0_um, cell.fill_gap_um, fluid.h0_um, fluid.h_over_dx). Throws InputError if the geometry is impossible.
Cell build_cell(Params& p);

// The N points of a cubic lattice (spacing 1, one point at the origin) nearest the origin, ties
// broken by index; returned with the lattice radius of the farthest one.
Eigen::Matrix3Xd nearest_lattice_points(int n, double* farthest);

// Rules for derived defaults, shared by build_cell and the docs.
inline constexpr double kR0OverCircumradius = 1.8;  // model.md §4
inline constexpr double kFillGapOverR0 = 0.7;       // model.md §1
inline constexpr double kReferenceH0_m = 6.8e-6;    // Table 3, for the default 150 um cell

}  // namespace cellsim
