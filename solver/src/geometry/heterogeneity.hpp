#pragma once
// Seeded heterogeneous properties (docs/model.md §3c; ours, off unless a coefficient of variation is
// given): a factor on each wall bond's shear modulus G and thickness t0, and on each cell's fluid
// viscosity mu. Each factor is lognormal with mean 1 and the given coefficient of variation (cv); over a
// wall the factors may be correlated over a length (a white noise on the bonds' midpoints smoothed by a
// Gaussian of that length, one cell's wall at a time). The same seed gives the same bits.
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "geometry/wall_mesh.hpp"

namespace cellsim {

struct HeterogeneityLaw {
  std::int64_t seed = 1;
  double G_cv = 0, thickness_cv = 0, viscosity_cv = 0;  // coefficients of variation (0: uniform)
  double correlation_length_m = 0;                      // over a wall (0: each bond its own draw)
};

struct PropertyFactors {
  std::vector<double> G, thickness;  // per wall bond
  std::vector<double> viscosity;     // per cell
};

// A lognormal factor of mean 1 and coefficient of variation cv from a standard normal z:
// exp(s z - s^2 / 2) with s^2 = ln(1 + cv^2). cv = 0 gives exactly 1.
double lognormal_factor(double z, double cv);

// n standard normals of stream `stream` of `seed` (Box-Muller on a 64-bit Mersenne twister, whose
// sequence the C++ standard fixes: the same bits on every platform).
std::vector<double> standard_normals(std::int64_t seed, int stream, std::size_t n);

// White noise at points, smoothed by exp(-d^2 / (2 length^2)) and scaled back to unit variance; only
// points of the same group (a cell's wall) are mixed. length = 0 returns the noise as it is.
std::vector<double> correlated_normals(const std::vector<double>& white, const Eigen::Matrix3Xd& points,
                                       const std::vector<int>& group, double length_m);

// The factors of a tissue's bonds (from its particles' positions as built) and cells.
PropertyFactors draw_property_factors(const HeterogeneityLaw& law, const Eigen::Matrix3Xd& wall_x, const WallMesh& mesh,
                                      const std::vector<int>& cell_of_wall, int cells);

}  // namespace cellsim
