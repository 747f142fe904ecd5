#pragma once
// The wall bond loop: stiff (Eq 15), contraction (Eq 21) and damping (Eq 16) forces on every
// bond, applied equal and opposite to its two particles.
#include <vector>

#include <Eigen/Core>

#include "parallel/owned_spans.hpp"

#include "core/params.hpp"
#include "core/state.hpp"
#include "geometry/heterogeneity.hpp"
#include "geometry/wall_mesh.hpp"
#include "physics/wall_plasticity.hpp"

namespace cellsim {

struct BondLaw {
  std::vector<double> G_t_N_m;     // G t0 of each bond, Eq 15 (times its factors: heterogeneity.hpp)
  std::vector<double> thickness_m; // t0 of each bond (the plastic wall's section)
  double contraction_N_m;          // k_wc, Eq 21
  double contraction_ratio;        // c = a/b, Eq 21
  double dryness;                  // X/X0
  double damping_N_s_m;            // gamma, Eq 16
  wall::PlasticLaw plastic;        // the elastic-plastic wall (wall_plasticity.hpp); inactive by default
};

// The law of the mesh's bonds: G, t0 and the rest of p, each bond's G and t0 times its factors.
BondLaw make_bond_law(const Params& p, const PropertyFactors& factors);

// What add_bond_forces sums up besides the forces.
struct BondSums {
  double tension_times_length = 0;  // sum of tension x length (the wall's mean tension, Young-Laplace)
  double damping_loss_W = 0;        // the power Eq 16 takes out of the wall (the energy account)
  // Sum of k_wc (l - L_ref) l0: the drying ramp's power is this x c (1 - X) d(ramp)/dt (L_ref =
  // l0 [1 - c (1 - X) ramp] shortens, and each spring's energy changes by -k_wc (l - L_ref) dL_ref).
  double contraction_times_l0_N_m = 0;
  double plastic_loss_J = 0;  // the energy the bonds that yielded at these positions dissipated (wall_plasticity.hpp)
};

// Kept by the caller between steps, so that no step allocates.
struct BondScratch {
  Eigen::VectorXd tension_over_length;        // per bond
  std::vector<double> tension_times_length;   // per thread
  OwnedSpans spans;                           // the bonds of each thread's particles (owned_spans.hpp)
};

// Adds to force (3 x N_w); ramp in [0, 1] scales the contraction of L_ref (model.md §5).
// plastic_elongation_m: each bond's slider delta_p (0 until it yields); a plastic law lengthens it at these
// positions before the forces (the return map of wall_plasticity.hpp).
BondSums add_bond_forces(const WallParticles& w, const WallMesh& mesh, const BondLaw& law, double ramp, int threads,
                         std::vector<double>& plastic_elongation_m, Eigen::Matrix3Xd& force, BondScratch& scratch);

// The energy stored in the bonds (the energy account): Eq 15's stiff springs and Eq 21's contraction springs.
struct BondEnergy {
  double stiff_J = 0, contraction_J = 0;
};
BondEnergy bond_energy(const WallParticles& w, const WallMesh& mesh, const BondLaw& law, double ramp,
                       const std::vector<double>& plastic_elongation_m);

}  // namespace cellsim
