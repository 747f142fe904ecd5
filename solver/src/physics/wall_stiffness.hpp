#pragma once
// The stiffness matrix of the wall's springs, -dF/dx, added into K (its pattern the bonds): each bond's
// Eq 15 and Eq 21 springs, k n n^T along the bond plus its tension's T / l (I - n n^T) across it (tension
// only). The springs' face of the force field's stiffness (engine/force_terms.hpp), exact at a fixed
// history; the compressed bonds' negative part across is left out.
#include <vector>

#include <Eigen/Core>

#include "core/state.hpp"
#include "geometry/block_stiffness.hpp"
#include "geometry/wall_mesh.hpp"
#include "physics/wall_bonds.hpp"

namespace cellsim {

// plastic_elongation_m: each bond's slider (wall_plasticity.hpp), held fixed: the elastic stiffness of a
// bond whose history is given.
void add_wall_spring_stiffness(const Eigen::Matrix3Xd& x, const WallMesh& mesh, const BondLaw& law, double ramp,
                               const std::vector<double>& plastic_elongation_m, BlockStiffness& K);

}  // namespace cellsim
