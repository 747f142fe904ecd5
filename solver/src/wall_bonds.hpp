#pragma once
// The wall bond loop: stiff (Eq 15), contraction (Eq 21) and damping (Eq 16) forces on every
// bond, applied equal and opposite to its two particles.
#include <Eigen/Core>

#include "state.hpp"
#include "wall_mesh.hpp"

namespace cellsim {

struct BondLaw {
  double G_Pa, thickness_m;        // Eq 15
  double contraction_N_m;          // k_wc, Eq 21
  double contraction_ratio;        // c = a/b, Eq 21
  double dryness;                  // X/X0
  double damping_N_s_m;            // gamma, Eq 16
};

// Adds to force (3 x N_w); ramp in [0, 1] scales the contraction of L_ref (model.md §5).
// Returns sum over bonds of tension x length (for the wall's mean tension, Young-Laplace).
// tension_over_length is scratch (kept by the caller to avoid reallocation), one value per bond.
double add_bond_forces(const WallParticles& w, const WallMesh& mesh, const BondLaw& law, double ramp,
                       Eigen::Matrix3Xd& force, Eigen::VectorXd& tension_over_length);

}  // namespace cellsim
