#include "geometry/cell.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <tuple>

#include "core/errors.hpp"
#include "geometry/hull.hpp"

namespace cellsim {
namespace {

struct WallAndFluid {
  Eigen::Matrix3Xd wall_x;
  WallMesh mesh;
  double r0_m;
  double fluid_spacing_m;
  Eigen::Matrix3Xd fluid_x;
  double fill_gap_m;
};

// The geometry shared by the case and the reference cell: only size and counts matter.
// The fill gap's default: 0.7 r0 outside the LJ layer's range; with the pressure coupling, half
// the fluid spacing, so that the fluid's volume (one spacing around each particle) reaches the wall.
WallAndFluid build_geometry(double radius, int n_wall, int n_fluid, std::optional<double> r0,
                            std::optional<double> fill_gap, Choice coupling = kLennardJones) {
  WallAndFluid g;
  g.wall_x = fibonacci_sphere(n_wall, radius);
  g.mesh = build_wall_mesh(g.wall_x, convex_hull_triangles(g.wall_x));
  g.r0_m = r0 ? *r0 : kR0OverCircumradius * largest_circumradius(g.wall_x, g.mesh.triangles);
  double farthest = 0;
  const Eigen::Matrix3Xd unit = nearest_lattice_points(n_fluid, &farthest);
  if (fill_gap)
    g.fill_gap_m = *fill_gap;
  else if (coupling == kPressure)
    g.fill_gap_m = 0.5 * radius / (farthest + 0.5);  // dx / 2 with dx = (R - dx / 2) / farthest
  else
    g.fill_gap_m = kFillGapOverR0 * g.r0_m;
  const double fill_radius = radius - g.fill_gap_m;
  if (!(fill_radius > 0)) {
    std::ostringstream msg;
    msg << "cell.fill_gap_um = " << g.fill_gap_m * 1e6 << ": must be smaller than the cell radius " << radius * 1e6
        << " um" << (fill_gap ? "" : " (it defaults to 0.7 r0: set coupling.r0_um or cell.fill_gap_um)");
    throw InputError(msg.str());
  }
  // Largest spacing with every point inside the fill radius; a lone particle sits at the centre.
  g.fluid_spacing_m = farthest > 0 ? fill_radius / farthest * (1.0 - 1e-12) : fill_radius;
  g.fluid_x = unit * g.fluid_spacing_m;
  return g;
}

// Fluid spacing of the paper's default cell (D = 150 um, 2067 / 3082): the dx_ref of Eq 6's h0 rule.
double reference_fluid_spacing() {
  static const double dx_ref = build_geometry(75e-6, 2067, 3082, std::nullopt, std::nullopt).fluid_spacing_m;
  return dx_ref;
}

}  // namespace

Eigen::Matrix3Xd nearest_lattice_points(int n, double* farthest) {
  const int m = static_cast<int>(std::ceil(std::cbrt(3.0 * n / (4.0 * M_PI)))) + 2;
  std::vector<std::tuple<int, int, int, int>> candidates;  // (r^2, i, j, k)
  for (int i = -m; i <= m; ++i)
    for (int j = -m; j <= m; ++j)
      for (int k = -m; k <= m; ++k) candidates.emplace_back(i * i + j * j + k * k, i, j, k);
  std::partial_sort(candidates.begin(), candidates.begin() + n, candidates.end());
  *farthest = std::sqrt(static_cast<double>(std::get<0>(candidates[static_cast<std::size_t>(n - 1)])));
  // Store them in Morton (Z-curve) order, so particles near in space are near in memory: the pair
  // loop's neighbours of consecutive particles then share cache lines (~7 % faster than z-major).
  const auto morton_key = [m](const auto& c) {
    const unsigned coords[3] = {static_cast<unsigned>(std::get<1>(c) + m), static_cast<unsigned>(std::get<2>(c) + m),
                                static_cast<unsigned>(std::get<3>(c) + m)};
    std::uint64_t key = 0;
    for (int bit = 0; bit < 21; ++bit)  // the bits of x, y, z interleaved
      for (int d = 0; d < 3; ++d) key |= static_cast<std::uint64_t>((coords[d] >> bit) & 1u) << (3 * bit + d);
    return key;
  };
  std::sort(candidates.begin(), candidates.begin() + n,
            [&](const auto& a, const auto& b) { return morton_key(a) < morton_key(b); });
  Eigen::Matrix3Xd x(3, n);
  for (int p = 0; p < n; ++p) {
    const auto& [r2, i, j, k] = candidates[static_cast<std::size_t>(p)];
    x.col(p) << i, j, k;
  }
  return x;
}

Cell build_cell(Params& p) {
  const double radius = 0.5 * p.diameter_m;
  WallAndFluid g = build_geometry(radius, static_cast<int>(p.n_wall), static_cast<int>(p.n_fluid), p.r0_m,
                                  p.fill_gap_m, p.coupling_model);
  p.r0_m = g.r0_m;
  p.fill_gap_m = g.fill_gap_m;
  if (p.h0_m && p.h_over_dx) {
    std::ostringstream msg;
    msg << "fluid.h0_um = " << *p.h0_m * 1e6 << " and fluid.h_over_dx = " << *p.h_over_dx
        << " both set the smoothing length: set one of them";
    throw InputError(msg.str());
  }
  if (!p.h0_m)  // the paper's h0 scaled with dx (as written, so the default's bits stay those of the rule)
    p.h0_m = p.h_over_dx ? *p.h_over_dx * g.fluid_spacing_m
                         : kReferenceH0_m * g.fluid_spacing_m / reference_fluid_spacing();
  p.h_over_dx = *p.h0_m / g.fluid_spacing_m;

  Cell cell;
  const double cell_volume = 4.0 / 3.0 * M_PI * radius * radius * radius;
  cell.fluid_mass_kg = p.fluid_density_kg_m3 * cell_volume / static_cast<double>(p.n_fluid);
  cell.wall_mass_kg = p.wall_mass_fraction * p.fluid_density_kg_m3 * cell_volume / static_cast<double>(p.n_wall);
  cell.wall_x = std::move(g.wall_x);
  cell.mesh = std::move(g.mesh);
  cell.fluid_x = std::move(g.fluid_x);
  cell.fluid_spacing_m = g.fluid_spacing_m;
  return cell;
}

}  // namespace cellsim
