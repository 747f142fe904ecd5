#include "geometry/heterogeneity.hpp"

#include <cmath>
#include <random>

namespace cellsim {

double lognormal_factor(double z, double cv) {
  if (cv == 0) return 1.0;
  const double s2 = std::log1p(cv * cv);
  return std::exp(std::sqrt(s2) * z - 0.5 * s2);
}

std::vector<double> standard_normals(std::int64_t seed, int stream, std::size_t n) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(seed) * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(stream));
  const auto uniform = [&] { return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53; };  // in (0, 1)
  std::vector<double> z(n);
  for (std::size_t i = 0; i < n; i += 2) {
    const double r = std::sqrt(-2.0 * std::log(uniform())), angle = 2.0 * M_PI * uniform();
    z[i] = r * std::cos(angle);
    if (i + 1 < n) z[i + 1] = r * std::sin(angle);
  }
  return z;
}

std::vector<double> correlated_normals(const std::vector<double>& white, const Eigen::Matrix3Xd& points,
                                       const std::vector<int>& group, double length_m) {
  if (length_m <= 0) return white;
  const auto n = static_cast<Eigen::Index>(white.size());
  std::vector<double> field(white.size());
  const double reach2 = 36.0 * length_m * length_m;  // beyond 6 lengths a weight is below 1.6e-8
  for (Eigen::Index a = 0; a < n; ++a) {
    // A sum of independent unit normals with weights w has variance sum w^2: dividing by its root keeps 1.
    double sum = 0, weight2 = 0;
    for (Eigen::Index b = 0; b < n; ++b) {
      if (group[static_cast<std::size_t>(b)] != group[static_cast<std::size_t>(a)]) continue;
      const double d2 = (points.col(a) - points.col(b)).squaredNorm();
      if (d2 > reach2) continue;
      const double w = std::exp(-0.5 * d2 / (length_m * length_m));
      sum += w * white[static_cast<std::size_t>(b)];
      weight2 += w * w;
    }
    field[static_cast<std::size_t>(a)] = sum / std::sqrt(weight2);
  }
  return field;
}

PropertyFactors draw_property_factors(const HeterogeneityLaw& law, const Eigen::Matrix3Xd& wall_x, const WallMesh& mesh,
                                      const std::vector<int>& cell_of_wall, int cells) {
  const std::size_t n_bonds = mesh.bonds.size();
  Eigen::Matrix3Xd midpoint(3, static_cast<Eigen::Index>(n_bonds));
  std::vector<int> cell_of_bond(n_bonds);
  for (std::size_t b = 0; b < n_bonds; ++b) {
    midpoint.col(static_cast<Eigen::Index>(b)) = 0.5 * (wall_x.col(mesh.bonds[b][0]) + wall_x.col(mesh.bonds[b][1]));
    cell_of_bond[b] = cell_of_wall.empty() ? 0 : cell_of_wall[static_cast<std::size_t>(mesh.bonds[b][0])];
  }
  const auto bond_factors = [&](int stream, double cv) {
    if (cv == 0) return std::vector<double>(n_bonds, 1.0);
    const std::vector<double> z =
        correlated_normals(standard_normals(law.seed, stream, n_bonds), midpoint, cell_of_bond, law.correlation_length_m);
    std::vector<double> factor(n_bonds);
    for (std::size_t b = 0; b < n_bonds; ++b) factor[b] = lognormal_factor(z[b], cv);
    return factor;
  };
  PropertyFactors f;
  f.G = bond_factors(1, law.G_cv);
  f.thickness = bond_factors(2, law.thickness_cv);
  const std::vector<double> z = standard_normals(law.seed, 3, static_cast<std::size_t>(cells));
  for (int c = 0; c < cells; ++c) f.viscosity.push_back(lognormal_factor(z[static_cast<std::size_t>(c)], law.viscosity_cv));
  return f;
}

}  // namespace cellsim
