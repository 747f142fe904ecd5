#pragma once
// The initial tissue (model.md §1, §10): cells side by side, each a closed wall with its own fluid.
// One cell (tissue.cells_* = 1) is the paper's cell. Particles are stored cell after cell, so each
// cell owns one contiguous range of the fluid, the wall and the wall's triangles.
#include <vector>

#include <Eigen/Core>

#include "core/params.hpp"
#include "core/periodic_box.hpp"
#include "geometry/wall_mesh.hpp"

namespace cellsim {

// Cell c owns fluid particles [fluid[c], fluid[c + 1]) and wall particles [wall[c], wall[c + 1])
// (and the triangles WallMesh::cell_triangles gives it), and sits in layer layer[c] along z (0 at the
// bottom; the one cell: layer 0).
struct CellRanges {
  std::vector<Eigen::Index> fluid{0}, wall{0};
  std::vector<int> layer;
  int layer_of(int c) const { return layer.empty() ? 0 : layer[static_cast<std::size_t>(c)]; }
  int layers() const;
  int count() const { return static_cast<int>(fluid.size()) - 1; }
  Eigen::Index fluid_count(int c) const { return fluid[c + 1] - fluid[c]; }
  Eigen::Index wall_count(int c) const { return wall[c + 1] - wall[c]; }
  // Which cell each particle belongs to (for the neighbour lists' filter).
  std::vector<int> cell_of_fluid() const;
  std::vector<int> cell_of_wall() const;
};

// A middle-lamella bond (model.md §10): wall particles a < b of different cells, at rest at length_m.
struct LamellaBond {
  int a, b;
  double length_m;
};

struct Tissue {
  Eigen::Matrix3Xd wall_x;        // wall particle positions [m]
  WallMesh mesh;                  // every cell's triangles, bonds and hinges
  Eigen::Matrix3Xd fluid_x;       // fluid particle positions [m]
  Eigen::VectorXd fluid_mass_kg;  // per fluid particle: rho0 V_c / N_c of its cell
  double wall_mass_kg = 0;        // per wall particle: fraction x rho0 (4/3) pi R^3 / N_w
  double fluid_spacing_m = 0;     // cubic lattice spacing dx (the same in every cell)
  CellRanges cells;
  std::vector<Eigen::Vector3d> centre_m;  // each cell's centre as built
  std::vector<LamellaBond> lamella;       // facing wall particles, bonded
  double wall_particle_area_m2 = 0;       // the area a wall particle owns: pi D0^2 / N_w
  PeriodicBox box;                        // tissue.lateral = periodic: the lateral period (else none)
};

// Builds the tissue of a resolved case (resolve_derived_geometry, cell.hpp), each cell by build_cell
// with the faces it meets its neighbours by. Throws InputError if the geometry is impossible. A periodic
// tissue's cells face their neighbours' images across the period as they face their neighbours.
Tissue build_tissue(const Params& p);

}  // namespace cellsim
