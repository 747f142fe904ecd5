#pragma once
// The initial cell (model.md §1): wall particles and mesh, fluid particles, masses. A case's derived
// parameters are resolved once, before anything is built (resolve_derived_geometry, called when a case
// is validated); then build_cell makes one cell, the paper's sphere or a tissue's cell flattened by its
// faces (CellShape), and a tissue is its cells (tissue.hpp).
#include <functional>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include "core/params.hpp"
#include "geometry/wall_mesh.hpp"

namespace cellsim {

// Fills in the derived parameters of p that are still unset, from the paper's cell of this case's size
// and counts: coupling.r0_um (from its mesh), cell.fill_gap_um, fluid.h0_um and fluid.h_over_dx (from its
// fluid lattice), tissue.wall_gap_um. Throws InputError if the geometry is impossible or both h0 and
// h0/dx are given.
void resolve_derived_geometry(Params& p);

// The fluid lattice's spacing dx of a resolved case: the largest with each of the N_f lattice points
// nearest the centre within R - fill gap (a lone particle sits at the centre).
double fluid_spacing_m(const Params& p);

// Per wall particle: fraction x rho0 (4/3) pi R^3 / N_w, the same in every cell of a tissue.
double wall_particle_mass_kg(const Params& p);

// One cell's shape about its centre: a sphere of radius_m whose wall particles lie on a spiral about
// spiral_axis, moved in by `onto_faces` where it meets its neighbours; the fluid lattice points inside
// the sphere that `holds_fluid` keeps (the tissue's faces less the fill gap). Unset functions: the
// free sphere (the paper's cell).
struct CellShape {
  double radius_m = 0;  // 0: the case's cell.diameter_um / 2
  Eigen::Vector3d spiral_axis = default_spiral_axis();
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> onto_faces;
  std::function<bool(const Eigen::Vector3d&)> holds_fluid;
};

struct Cell {
  Eigen::Matrix3Xd wall_x;      // wall particle positions [m], about the origin
  WallMesh mesh;
  Eigen::Matrix3Xd fluid_x;     // fluid particle positions [m]
  double fluid_mass_kg = 0;     // per fluid particle: rho0 x (the sphere's volume as the faces cut it) / count
  double wall_mass_kg = 0;      // per wall particle (wall_particle_mass_kg)
  double fluid_spacing_m = 0;   // cubic lattice spacing dx
};

// One cell of a resolved case (resolve_derived_geometry), centred on the origin. The wall has
// N_w (r / R)^2 particles and the fluid lattice N_f (r / R)^3 points before the faces take theirs.
// A shape whose faces leave no fluid gives a cell without fluid (the tissue names the case's keys); so
// does fluid.model = cavity, whose fluid is no particles (engine/cavity_fluid.hpp).
Cell build_cell(const Params& p, const CellShape& shape = {});
// The same with the case's fluid spacing given (a tissue's cells share it: fluid_spacing_m).
Cell build_cell(const Params& p, const CellShape& shape, double fluid_spacing);

// The N points of a cubic lattice (spacing 1, one point at the origin) nearest the origin, ties
// broken by index; returned with the lattice radius of the farthest one.
Eigen::Matrix3Xd nearest_lattice_points(int n, double* farthest);

// Rules for derived defaults, shared by resolve_derived_geometry and the docs.
inline constexpr double kR0OverCircumradius = 1.8;  // model.md §4
inline constexpr double kFillGapOverR0 = 0.7;       // model.md §1
inline constexpr double kReferenceH0_m = 6.8e-6;    // Table 3, for the default 150 um cell

}  // namespace cellsim
