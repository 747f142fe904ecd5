#pragma once
// Compression plates, Eq 22 (model.md §3, §6): a wall particle closer than r_pw to a plate and
// inside the plate's footprint is pushed away from it with k_pw (r_pw - d). The reaction on the
// plate is the plate force.
#include <Eigen/Core>

#include "core/params.hpp"
#include "core/state.hpp"
#include "geometry/block_stiffness.hpp"

namespace cellsim {

struct PlateLaw {
  double range_m;        // r_pw
  double stiffness_N_m;  // k_pw
  double length_m;       // footprint along x, centred on the plates' axis
  double width_m;        // footprint along y
};

PlateLaw plate_law(const Params& p);

// Eq 22's contact rule, decided here and nowhere else: how far wall particle x reaches into the
// range r_pw of each plate; 0 when it is out of range or outside the plate's footprint.
struct PlateOverlap {
  double top_m = 0, bottom_m = 0;
  bool touches() const { return top_m > 0 || bottom_m > 0; }
};
PlateOverlap plate_overlap(const Eigen::Vector3d& x, const PlateLaw& law, const Plates& plates);

// The energy stored in Eq 22's springs, sum of k_pw overlap^2 / 2 over both plates (the energy account).
double plate_energy_J(const Eigen::Matrix3Xd& wall_x, const PlateLaw& law, const Plates& plates);

// Adds the plate forces to wall_force and sets plates.force_top_N, force_bottom_N and contacts.
// threads: as `cellsim run --threads` (the plate forces are summed in fixed blocks, threads.hpp).
void add_plate_forces(const Eigen::Matrix3Xd& wall_x, const PlateLaw& law, Plates& plates, Eigen::Matrix3Xd& wall_force,
                      int threads = 1);

// Eq 22's stiffness, -dF/dx, added into K: k_pw along z on each wall particle a plate touches (the
// force field's plates face, engine/force_terms.hpp); nothing while the plates are not placed.
void add_plate_stiffness(const Eigen::Matrix3Xd& wall_x, const PlateLaw& law, const Plates& plates, BlockStiffness& K);

}  // namespace cellsim
