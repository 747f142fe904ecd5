#pragma once
// The stiffness matrix of the wall's springs, -dF/dx, added into K (its pattern the bonds): each bond's
// Eq 15 and Eq 21 springs, k n n^T along the bond plus its tension's T / l (I - n n^T) across it (tension
// only), and Eq 22's k_pw along z on a particle a plate touches. Bending, the fluid and a tissue's contacts
// are left out: it is the springs' part of what the quasi-static Newton steps precondition with
// (engine/newton_preconditioner.hpp; exact for the springs at a fixed history), not the Hessian itself;
// shift_N_m on the diagonal keeps the free motions (sliding between frictionless plates, turning about z)
// from making it singular.
#include <vector>

#include <Eigen/Core>

#include "core/state.hpp"
#include "geometry/block_stiffness.hpp"
#include "geometry/wall_mesh.hpp"
#include "physics/plates.hpp"
#include "physics/wall_bonds.hpp"

namespace cellsim {

// plastic_elongation_m: each bond's slider (wall_plasticity.hpp), held fixed: the elastic stiffness of a
// bond whose history is given.
void add_wall_spring_stiffness(const Eigen::Matrix3Xd& x, const WallMesh& mesh, const BondLaw& law, double ramp,
                               const std::vector<double>& plastic_elongation_m, const PlateLaw& plate_law,
                               const Plates& plates, double shift_N_m, BlockStiffness& K);

// The fluid's share, added into K, for closed cells of uniform pressure P (cavity_fluid.hpp): -P d2V/dx2
// of each cell's enclosed volume at fixed P, the follower stiffness of a pressure that turns with the
// wall. Symmetric, indefinite; a cell's blocks join only the corners of its triangles (the bonds' pattern).
void add_pressure_follower_stiffness(const Eigen::Matrix3Xd& x, const WallMesh& mesh,
                                     const std::vector<double>& cell_pressure_Pa, BlockStiffness& K);

}  // namespace cellsim
