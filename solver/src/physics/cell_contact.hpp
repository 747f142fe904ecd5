#pragma once
// Forces between the walls of different cells (model.md §10). Contact: wall particles of different
// cells closer than the wall gap g repel, F = k_c (g - r) along the line between them (Eq 22's form,
// as between a plate and the wall). Middle lamella: bonded facing particles pull back to their initial
// distance l0 by the cohesive law of lamella_law.hpp, and separate for good once opened past delta_f.
#include <vector>

#include <Eigen/Core>

#include "geometry/block_stiffness.hpp"
#include "geometry/neighbours.hpp"
#include "core/periodic_box.hpp"
#include "geometry/tissue.hpp"
#include "physics/lamella_law.hpp"

namespace cellsim {

struct CellContactLaw {
  double gap_m = 0;
  double contact_stiffness_N_m = 0;
  LamellaLaw lamella;
};

// Adds the contact and lamella forces to wall_force (each pair's two forces are equal and opposite,
// along the line to the partner's nearest image in a periodic tissue: model.md §10b). Each bond's
// largest opening so far is kept in peak_opening_m; a bond whose peak reaches delta_f is marked
// separated in `intact` before it acts. Returns how many separated now. period_virial_J, if given,
// receives the x and y parts of sum s (x) f over the pairs that act across the period (s: the period
// shift that takes the partner to its nearest image, f: the force on the particle it is seen from),
// the whole lateral virial of a periodic tissue at rest (model.md §10b).
int add_cell_contact_forces(const Eigen::Matrix3Xd& wall_x, const PairList& wall_wall,
                            const std::vector<LamellaBond>& bonds, const CellContactLaw& law, const PeriodicBox& box,
                            std::vector<char>& intact, std::vector<double>& peak_opening_m,
                            Eigen::Matrix3Xd& wall_force, Eigen::Vector2d* period_virial_J = nullptr);

// Their stiffness, -dF/dx, added into K where K's pattern joins the pair (the quasi-static
// preconditioner, engine/newton_preconditioner.hpp; a contact that came into reach after the pattern was
// laid out is left to the Newton steps' products). A contact closer than g: k_c n n^T along its line (the
// part across it, -k_c (g - r) / r, is negative and left out, as a compressed bond's). An intact lamella
// bond: its law's slope along the line at its history (the secant of a damaged bond, which is where
// it returns to while the history holds) and its tension T / r across when pulled. Returns the number
// of pairs in reach that K's pattern does not join.
int add_cell_contact_stiffness(const Eigen::Matrix3Xd& wall_x, const PairList& wall_wall,
                               const std::vector<LamellaBond>& bonds, const CellContactLaw& law,
                               const PeriodicBox& box, const std::vector<char>& intact,
                               const std::vector<double>& peak_opening_m, BlockStiffness& K);

// The energies of these forces (the energy account): the contacts' k_c (g - r)^2 / 2 over the pairs
// closer than g, the intact bonds' stored energy and every bond's dissipated energy (lamella_law.hpp).
struct CellContactEnergy {
  double contact_J = 0;
  double lamella_J = 0;
  double lamella_dissipated_J = 0;
};
CellContactEnergy cell_contact_energy(const Eigen::Matrix3Xd& wall_x, const PairList& wall_wall,
                                      const std::vector<LamellaBond>& bonds, const CellContactLaw& law,
                                      const PeriodicBox& box, const std::vector<char>& intact,
                                      const std::vector<double>& peak_opening_m);

}  // namespace cellsim
