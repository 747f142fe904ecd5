#include "geometry/cell.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "core/errors.hpp"
#include "geometry/hull.hpp"
#include "geometry/surface.hpp"

namespace cellsim {
namespace {

// model.md §4: r0 = 1.8 x the largest circumradius of the wall's triangles, on the sphere of this
// radius and count (the free cell's mesh).
double derived_r0_m(double radius, int n_wall) {
  const Eigen::Matrix3Xd sphere = fibonacci_sphere(n_wall, radius);
  // the mesh's triangles (each rotated to its smallest vertex), whose circumradii the cell's own are
  return kR0OverCircumradius * largest_circumradius(sphere, build_wall_mesh(sphere, convex_hull_triangles(sphere)).triangles);
}

// The lattice radius (in spacings) of the farthest of the N_f lattice points nearest the centre.
double lattice_farthest(int n_fluid) {
  double farthest = 0;
  nearest_lattice_points(n_fluid, &farthest);
  return farthest;
}

// The fill gap's default: 0.7 r0 outside the LJ layer's range; with the pressure coupling, half the
// fluid spacing, so that the fluid's volume (one spacing around each particle) reaches the wall.
double default_fill_gap_m(double radius, double farthest, double r0_m, Choice coupling) {
  if (coupling == kPressure) return 0.5 * radius / (farthest + 0.5);  // dx / 2 with dx = (R - dx / 2) / farthest
  return kFillGapOverR0 * r0_m;
}

// Largest spacing with every point inside the fill radius; a lone particle sits at the centre.
// fill_gap_given: the gap was the case's own (else a default, which the message explains).
double lattice_spacing_m(double radius, double fill_gap_m, double farthest, bool fill_gap_given) {
  const double fill_radius = radius - fill_gap_m;
  if (!(fill_radius > 0)) {
    std::ostringstream msg;
    msg << "cell.fill_gap_um = " << fill_gap_m * 1e6 << ": must be smaller than the cell radius " << radius * 1e6
        << " um" << (fill_gap_given ? "" : " (it defaults to 0.7 r0: set coupling.r0_um or cell.fill_gap_um)");
    throw InputError(msg.str());
  }
  return farthest > 0 ? fill_radius / farthest * (1.0 - 1e-12) : fill_radius;
}

// Fluid spacing of the paper's default cell (D = 150 um, 2067 / 3082, LJ): the dx_ref of Eq 6's h0 rule.
double reference_fluid_spacing() {
  static const double dx_ref = [] {
    const double radius = 75e-6, farthest = lattice_farthest(3082);
    const double fill_gap = default_fill_gap_m(radius, farthest, derived_r0_m(radius, 2067), kLennardJones);
    return lattice_spacing_m(radius, fill_gap, farthest, false);
  }();
  return dx_ref;
}

}  // namespace

void resolve_derived_geometry(Params& p) {
  const double radius = 0.5 * p.diameter_m;
  const int n_wall = static_cast<int>(p.n_wall), n_fluid = static_cast<int>(p.n_fluid);
  const double farthest = lattice_farthest(n_fluid);
  const bool fill_gap_given = p.fill_gap_m.has_value();
  if (!p.r0_m) p.r0_m = derived_r0_m(radius, n_wall);
  if (!p.fill_gap_m) p.fill_gap_m = default_fill_gap_m(radius, farthest, *p.r0_m, p.coupling_model);
  const double dx = lattice_spacing_m(radius, *p.fill_gap_m, farthest, fill_gap_given);
  // Both given: the same h (a case as `cellsim validate` prints it, to 15 digits) is h0; two different
  // ones are refused.
  if (p.h0_m && p.h_over_dx && std::abs(*p.h0_m - *p.h_over_dx * dx) > 1e-12 * *p.h0_m) {
    std::ostringstream msg;
    msg << "fluid.h0_um = " << *p.h0_m * 1e6 << " and fluid.h_over_dx = " << *p.h_over_dx
        << " both set the smoothing length, and differ (this cell's h0/dx = " << *p.h0_m / dx
        << "): set one of them";
    throw InputError(msg.str());
  }
  if (!p.h0_m)  // the paper's h0 scaled with dx (as written, so the default's bits stay those of the rule)
    p.h0_m = p.h_over_dx ? *p.h_over_dx * dx : kReferenceH0_m * dx / reference_fluid_spacing();
  p.h_over_dx = *p.h0_m / dx;
  if (!p.wall_gap_m) {  // model.md §10: facing walls one wall thickness apart
    if (!(p.thickness_m > 0))
      throw InputError("tissue.wall_gap_um derives from wall.thickness_um = 0 (facing walls one thickness apart) "
                       "and must be positive: give tissue.wall_gap_um, or a wall thicker than 0");
    p.wall_gap_m = p.thickness_m;
  }
}

double fluid_spacing_m(const Params& p) {
  return lattice_spacing_m(0.5 * p.diameter_m, p.fill_gap_m.value(), lattice_farthest(static_cast<int>(p.n_fluid)),
                           true);
}

double wall_particle_mass_kg(const Params& p) {
  const double radius = 0.5 * p.diameter_m;
  const double cell_volume = 4.0 / 3.0 * M_PI * radius * radius * radius;
  return p.wall_mass_fraction * p.fluid_density_kg_m3 * cell_volume / static_cast<double>(p.n_wall);
}

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

Cell build_cell(const Params& p, const CellShape& shape, double fluid_spacing) {
  const double radius = 0.5 * p.diameter_m;
  const double rc = shape.radius_m > 0 ? shape.radius_m : radius, scale = rc / radius;
  Cell cell;
  cell.fluid_spacing_m = fluid_spacing;
  cell.wall_mass_kg = wall_particle_mass_kg(p);
  // The wall: a sphere with the wall's particle spacing, each point moved onto the faces; its
  // triangles are the sphere's (every point stays on a ray from the centre: still outward).
  const int n_wall = static_cast<int>(std::lround(static_cast<double>(p.n_wall) * scale * scale));
  const Eigen::Matrix3Xd sphere = fibonacci_sphere(n_wall, rc, shape.spiral_axis);
  const std::vector<std::array<int, 3>> triangles = convex_hull_triangles(sphere);
  cell.wall_x = sphere;
  if (shape.onto_faces)
    for (Eigen::Index k = 0; k < sphere.cols(); ++k) cell.wall_x.col(k) = shape.onto_faces(sphere.col(k));
  cell.mesh = build_wall_mesh(cell.wall_x, triangles);
  if (p.fluid_model == kCavityFluid) return cell;  // a closed cell of one pressure: no particles
  // The fluid: the lattice points the sphere of rc would hold, less those the faces take.
  double farthest = 0;
  const Eigen::Matrix3Xd lattice =
      nearest_lattice_points(static_cast<int>(std::lround(static_cast<double>(p.n_fluid) * scale * scale * scale)),
                             &farthest) *
      fluid_spacing;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < lattice.cols(); ++i)
    if (!shape.holds_fluid || shape.holds_fluid(lattice.col(i))) kept.push_back(i);
  cell.fluid_x.resize(3, static_cast<Eigen::Index>(kept.size()));
  for (std::size_t i = 0; i < kept.size(); ++i) cell.fluid_x.col(static_cast<Eigen::Index>(i)) = lattice.col(kept[i]);
  // Its fluid mass: rho0 times the sphere's volume, cut as the faces cut the wall's.
  const double sphere_volume = 4.0 / 3.0 * M_PI * rc * rc * rc;
  const double cut =
      shape.onto_faces ? wall_surface(cell.wall_x, cell.mesh).volume_m3 / wall_surface(sphere, cell.mesh).volume_m3 : 1.0;
  if (!kept.empty())
    cell.fluid_mass_kg = p.fluid_density_kg_m3 * (sphere_volume * cut) / static_cast<double>(cell.fluid_x.cols());
  return cell;
}

Cell build_cell(const Params& p, const CellShape& shape) { return build_cell(p, shape, fluid_spacing_m(p)); }

}  // namespace cellsim
