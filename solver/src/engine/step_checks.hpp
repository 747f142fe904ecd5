#pragma once
// The time step's limits and the checks every step makes (model.md §7): the wall springs' limit, known
// before the first step; the fluid's CFL limits at the current forces; every particle finite and every
// density and mass positive. A check returns what is wrong in words ("" if nothing), for the engine to
// name the step and the stage.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/params.hpp"
#include "core/state.hpp"
#include "geometry/tissue.hpp"
#include "geometry/wall_mesh.hpp"
#include "physics/wall_bonds.hpp"

namespace cellsim {

// Stable leapfrog needs dt < 2 / omega_max; omega_max^2 <= 2 max_k (sum of spring constants at k) / m,
// over the wall's bonds (Eq 15 and 21 at rest), the middle lamella, a tissue's contacts and the plates.
double wall_spring_dt_limit_s(const WallMesh& mesh, const BondLaw& bonds, const std::vector<LamellaBond>& lamella,
                              const Params& p, double wall_mass_kg, Eigen::Index wall_count);

// What the fluid's limits ask of dt at this state and these forces: 0.25 h / (c0 + |v|max) (sound),
// 0.125 h^2 rho0 / mu (viscous, with the largest viscosity of any cell; none if 0) and
// 0.25 sqrt(h / |a|max) (acceleration). "" if dt is within every one, else which it exceeds.
std::string time_step_violation(const FluidParticles& f, const Eigen::Matrix3Xd& fluid_force, double h_m,
                                 double sound_speed_m_s, double largest_viscosity_Pa_s, double rho0_kg_m3, double dt_s,
                                 int threads);

// "" if every position and velocity is finite and every fluid density and mass positive and finite; else
// the first particle at fault and what of it.
std::string unsound_particle(const State& s, int threads);

// True if every entry of particles [begin, end) of f, of w, is sound as above (one packed pass per array).
bool fluid_is_sound(const FluidParticles& f, Eigen::Index begin, Eigen::Index end);
bool wall_is_finite(const WallParticles& w, Eigen::Index begin, Eigen::Index end);

// a - a is 0 for a finite entry and NaN otherwise, so the sum of a - a is exactly 0 iff every entry is
// finite (and cannot overflow, unlike the sum of a).
template <class Derived>
bool all_finite(const Eigen::DenseBase<Derived>& a) {
  return (a.derived().array() - a.derived().array()).sum() == 0.0;
}

}  // namespace cellsim
