#pragma once
// The most particles one run builds: a case past it is refused before anything is built, so that a
// count typed with a digit too many says so instead of filling the memory (about 1 kB a particle with
// its neighbour lists: 2e7 particles need some 20 GB; the finest wall of the closed-cell ladder, 66 k
// particles a cell, is 300 such cells).
#include <cstdint>
#include <sstream>

#include "core/errors.hpp"
#include "core/params.hpp"

namespace cellsim {

inline constexpr double kMostParticles = 2e7;

inline double particle_count(const Params& p) {
  const double cells = static_cast<double>(p.cells_x) * static_cast<double>(p.cells_y) * static_cast<double>(p.cells_z);
  return cells * (static_cast<double>(p.n_wall) + static_cast<double>(p.n_fluid));
}

inline void check_case_size(const Params& p) {
  const double particles = particle_count(p);
  if (particles <= kMostParticles) return;
  std::ostringstream msg;
  msg << "tissue.cells_x x cells_y x cells_z = " << p.cells_x * p.cells_y * p.cells_z
      << " cells of cell.n_wall + cell.n_fluid = " << p.n_wall + p.n_fluid << " particles: " << particles
      << " particles in all, more than one run builds (" << kMostParticles << "); give fewer cells or particles";
  throw InputError(msg.str());
}

}  // namespace cellsim
