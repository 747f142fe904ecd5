#pragma once
// The fluid-fluid pair loop: continuity (Eq 10), pressure (Eq 3) and viscous (Eq 4) terms over
// a half pair list, each pair visited once and applied to both particles.
#include <vector>

#include <Eigen/Core>

#include "core/state.hpp"
#include "geometry/neighbours.hpp"
#include "physics/eos.hpp"
#include "physics/kernel.hpp"

namespace cellsim {

struct FluidRates {
  Eigen::Matrix3Xd force;   // [N]
  Eigen::VectorXd drho_dt;  // continuity part only [kg/m^3/s]
  Eigen::VectorXd pressure; // EOS pressure [Pa]
  double viscous_loss_W = 0; // power Eq 4 takes out of the fluid, sum over pairs of -F_visc,ij . v_ij
  double density_diffusion_W = 0;  // internal energy the delta-SPH diffusion adds, sum of m P/rho^2 d(rho)/dt
  // Scratch of the pair loop, kept to avoid reallocation: one record per particle, and the sums
  // of each thread (fluid_pairs.cpp says what they hold).
  Eigen::Matrix<double, 12, Eigen::Dynamic> records;
  std::vector<Eigen::Matrix4Xd> thread_sums;
  // Block t: rows [first_row[t], first_row[t + 1]), and the later particles its pairs reach (its
  // halo, ascending), found once per build of the list (halo_build) and thread count.
  std::vector<int> first_row;
  std::vector<std::vector<int>> halo;
  std::vector<std::vector<char>> halo_mark;
  long halo_build = -1;
  std::vector<int> written;  // block t wrote records [first_row[t], written[t]) before the barrier
  std::vector<double> block_viscous_loss_W, block_diffusion_W;  // per block, added in block order
  // A continuity pass's (1/r) dW/dr of each slot of the list (padding: 0), for the forces pass at the
  // same positions (time.density_update = drift): the two passes share every pair's distance.
  std::vector<double> pair_gradient;
};

// The fluid's viscosity mu (Eq 4): one value, or one per particle (a cell's, heterogeneity.hpp). Fluid
// pairs never join two cells (neighbours.hpp), so a pair's mu_i + mu_j is 2 mu_i.
struct Viscosity {
  Viscosity(double uniform) : uniform_Pa_s(uniform) {}  // NOLINT: a number is a uniform viscosity
  Viscosity(double uniform, const double* per_particle) : uniform_Pa_s(uniform), per_particle_Pa_s(per_particle) {}
  double uniform_Pa_s;
  const double* per_particle_Pa_s = nullptr;  // null: uniform_Pa_s everywhere
};

// Which terms a pass over the pairs computes: all of them (the density kicked with the velocity, one
// pass a step), or, with the density advanced in the drift (time.density_update = drift), the
// continuity terms in one pass (Eq 10, and delta-SPH) and the forces in another (Eqs 3, 4).
enum class PairTerms { All, Continuity, Forces };

// Overwrites out (sized to the fluid); the terms a pass leaves out come out as zeros. threads: 1, or up to kMaxThreads with OpenMP (threads.hpp).
// density_diffusion_m2_s: delta h c0 of the delta-SPH density diffusion (sph_terms.hpp), 0 for none.
// continuity_pass (a Forces pass only): a Continuity pass over the same list at the same positions and
// h, whose kernel gradients are used in place of computing them (the same bits).
// A Continuity pass without the diffusion uses no pressure: it leaves out.pressure unset.
void fluid_pair_terms(const FluidParticles& f, const PairList& pairs, const CubicSplineKernel& kernel,
                      const EquationOfState& eos, Viscosity viscosity, int threads, FluidRates& out,
                      double density_diffusion_m2_s = 0, PairTerms terms = PairTerms::All,
                      const FluidRates* continuity_pass = nullptr);

}  // namespace cellsim
