#pragma once
// The wall bond loop: stiff (Eq 15), contraction (Eq 21) and damping (Eq 16) forces on every
// bond, applied equal and opposite to its two particles.
#include <vector>

#include <Eigen/Core>

#include "parallel/owned_spans.hpp"

#include "core/state.hpp"
#include "geometry/wall_mesh.hpp"

namespace cellsim {

struct BondLaw {
  double G_Pa, thickness_m;        // Eq 15
  double contraction_N_m;          // k_wc, Eq 21
  double contraction_ratio;        // c = a/b, Eq 21
  double dryness;                  // X/X0
  double damping_N_s_m;            // gamma, Eq 16
};

// Kept by the caller between steps, so that no step allocates.
struct BondScratch {
  Eigen::VectorXd tension_over_length;        // per bond
  std::vector<double> tension_times_length;   // per thread
  OwnedSpans spans;                           // the bonds of each thread's particles (owned_spans.hpp)
};

// Adds to force (3 x N_w); ramp in [0, 1] scales the contraction of L_ref (model.md §5).
// Returns sum over bonds of tension x length (for the wall's mean tension, Young-Laplace).
double add_bond_forces(const WallParticles& w, const WallMesh& mesh, const BondLaw& law, double ramp, int threads,
                       Eigen::Matrix3Xd& force, BondScratch& scratch);

}  // namespace cellsim
