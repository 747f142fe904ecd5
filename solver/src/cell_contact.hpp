#pragma once
// Forces between the walls of different cells (model.md §10). Contact: wall particles of different
// cells closer than the wall gap g repel, F = k_c (g - r) along the line between them (Eq 22's form,
// as between a plate and the wall). Middle lamella: bonded facing particles pull back to their initial
// distance l0, F = k_ml (r - l0); a bond whose tension exceeds its strength breaks for good.
#include <vector>

#include <Eigen/Core>

#include "neighbours.hpp"
#include "tissue.hpp"

namespace cellsim {

struct CellContactLaw {
  double gap_m = 0;
  double contact_stiffness_N_m = 0;
  double lamella_stiffness_N_m = 0;
  double lamella_break_force_N = 0;
};

// Adds the contact and lamella forces to wall_force (each pair's two forces are equal and opposite).
// Bonds whose tension exceeds the break force are marked broken in `intact` before they act; returns
// how many broke now.
int add_cell_contact_forces(const Eigen::Matrix3Xd& wall_x, const PairList& wall_wall,
                            const std::vector<LamellaBond>& bonds, const CellContactLaw& law,
                            std::vector<char>& intact, Eigen::Matrix3Xd& wall_force);

}  // namespace cellsim
