#include "geometry/tissue.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "core/errors.hpp"
#include "geometry/cell.hpp"
#include "geometry/hull.hpp"
#include "geometry/surface.hpp"

namespace cellsim {
namespace {

// A lamella bond joins facing wall particles up to this multiple of the wall gap apart (facing
// layers are one gap apart; the particles of two faces do not line up, so partners sit a little farther).
constexpr double kLamellaRangeOverGap = 1.5;
// A face may not cut a cell closer to its centre than this fraction of its radius.
constexpr double kSmallestFaceDistance = 0.3;

// A face of a cell: the points x with x . normal = distance (from the cell's centre) bound it. Across
// it lies cell `neighbour`, moved by `image` (a multiple of the period; zero in a cluster).
struct Face {
  Eigen::Vector3d normal;
  double distance_m;
  int neighbour;
  Eigen::Vector3d image;
};

std::vector<Eigen::Vector3d> lattice_centres(const Params& p, double distance_m) {
  std::vector<Eigen::Vector3d> centres;
  for (std::int64_t k = 0; k < p.cells_z; ++k)
    for (std::int64_t j = 0; j < p.cells_y; ++j)
      for (std::int64_t i = 0; i < p.cells_x; ++i) {
        Eigen::Vector3d c(static_cast<double>(i), static_cast<double>(j), static_cast<double>(k));
        if (p.packing == kClosePacking) {
          // Hexagonal layers (rows shifted by half), stacked A, B, C: face-centred cubic.
          const double layer = static_cast<double>(k % 3);
          c = Eigen::Vector3d(static_cast<double>(i) + 0.5 * static_cast<double>(j % 2) + 0.5 * layer,
                              std::sqrt(3.0) / 2.0 * static_cast<double>(j) + layer / (2.0 * std::sqrt(3.0)),
                              std::sqrt(2.0 / 3.0) * static_cast<double>(k));
        }
        centres.push_back(distance_m * c);
      }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& c : centres) mean += c;
  mean /= static_cast<double>(centres.size());
  for (auto& c : centres) c -= mean;  // the tissue centred on the origin (one cell: at the origin)
  return centres;
}

// tissue.lateral = periodic: the period holds cells_x x cells_y cells of the lattice (model.md §10b).
PeriodicBox lattice_period(const Params& p, double distance_m) {
  if (p.lateral == kLateralFree) {
    if (p.compression_lateral == kLateralUnconfined)
      throw InputError("compression.lateral = unconfined needs tissue.lateral = periodic: a cell or a cluster has no "
                       "period to follow (its sides are free)");
    return {};
  }
  if (p.cells_x < 2 || p.cells_y < 2)
    throw InputError("tissue.lateral = periodic needs tissue.cells_x and tissue.cells_y of at least 2 (got " +
                     std::to_string(p.cells_x) + " x " + std::to_string(p.cells_y) +
                     "): with one cell to a period a cell would face its own image");
  if (p.packing == kClosePacking && p.cells_y % 2)
    throw InputError("tissue.lateral = periodic with tissue.packing = close needs an even tissue.cells_y (got " +
                     std::to_string(p.cells_y) + "): the hexagonal rows alternate, so the period is two rows");
  const double row = p.packing == kClosePacking ? std::sqrt(3.0) / 2.0 : 1.0;
  return {distance_m * static_cast<double>(p.cells_x), distance_m * row * static_cast<double>(p.cells_y)};
}

// The images of a cell that may face another: itself, and in a periodic tissue its eight lateral
// neighbours' (the period is at least two cells, so no farther image comes within reach).
std::vector<Eigen::Vector3d> lateral_images(const PeriodicBox& box) {
  std::vector<Eigen::Vector3d> images{Eigen::Vector3d::Zero()};
  if (!box.periodic()) return images;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      if (i || j) images.emplace_back(i * box.length_x_m, j * box.length_y_m, 0.0);
  return images;
}

// R (1 + spread z), z a seeded standard normal clipped to +-2 (Box-Muller on mt19937_64, which the
// standard fixes bit for bit, unlike std::normal_distribution).
std::vector<double> cell_radii(const Params& p, std::size_t count) {
  const double radius = 0.5 * p.diameter_m;
  std::vector<double> radii(count, radius);
  if (p.diameter_spread == 0) return radii;
  std::mt19937_64 random(static_cast<std::uint64_t>(p.tissue_seed));
  const auto uniform = [&] { return (static_cast<double>(random() >> 11) + 0.5) * 0x1.0p-53; };
  for (auto& r : radii) {
    const double z = std::sqrt(-2.0 * std::log(uniform())) * std::cos(2.0 * M_PI * uniform());
    r = radius * (1.0 + p.diameter_spread * std::clamp(z, -2.0, 2.0));
  }
  return radii;
}

// The faces of cell a: the radical plane with each cell whose sphere comes within the wall gap of a's,
// moved back by half the gap, so that facing walls are one gap apart.
std::vector<Face> faces_of(int a, const std::vector<Eigen::Vector3d>& centres, const std::vector<double>& radii,
                           double gap_m, const PeriodicBox& box) {
  std::vector<Face> faces;
  for (int b = 0; b < static_cast<int>(centres.size()); ++b)
    for (const Eigen::Vector3d& image : lateral_images(box)) {
      if (b == a && image.isZero()) continue;
      const Eigen::Vector3d ab = centres[b] + image - centres[a];
      const double d = ab.norm(), ra = radii[a], rb = radii[b];
      if (d >= ra + rb + gap_m) continue;  // nowhere nearer than the wall gap: no face between them
      const double distance = (d * d + ra * ra - rb * rb) / (2.0 * d) - 0.5 * gap_m;
      if (distance < kSmallestFaceDistance * ra) {
        std::ostringstream msg;
        msg << "tissue: cells " << a << " and " << b << " overlap too much (a face " << distance * 1e6
            << " um from the centre of a cell of radius " << ra * 1e6
            << " um); raise tissue.centre_distance_over_diameter, or lower tissue.diameter_spread or tissue.wall_gap_um";
        throw InputError(msg.str());
      }
      faces.push_back({ab / d, distance, b, image});
    }
  return faces;
}

// A point of the sphere (relative to the centre) moved in along its radius onto the nearest face
// that cuts it; points no face cuts stay as they are (bit for bit: the one-cell tissue is the cell).
Eigen::Vector3d onto_faces(const Eigen::Vector3d& x, double radius, const std::vector<Face>& faces) {
  double r = radius;
  const Eigen::Vector3d u = x / radius;
  for (const auto& f : faces) {
    const double along = u.dot(f.normal);
    if (along > 0 && f.distance_m < r * along) r = f.distance_m / along;
  }
  return r < radius ? Eigen::Vector3d(r * u) : x;
}

// The spiral's axis for a cell with these faces: its poles (the wall's least regular triangles, which
// hold the fluid least well) as far from every face and its rim as the candidates allow, and at least
// kLatticeRowClearance from every low-index row of the fluid lattice (a row ending under a pole leaks:
// wall_mesh.cpp). No faces: the single cell's default axis.
constexpr double kLatticeRowClearance = 0.1;  // rad, about 6 degrees
Eigen::Vector3d spiral_axis(const std::vector<Face>& faces) {
  if (faces.empty()) return default_spiral_axis();
  std::vector<Eigen::Vector3d> rows;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k)
        if (i || j || k) rows.push_back(Eigen::Vector3d(i, j, k).normalized());
  const Eigen::Matrix3Xd candidates = fibonacci_sphere(500, 1.0);
  Eigen::Vector3d best = default_spiral_axis();
  double best_score = INFINITY;
  for (Eigen::Index c = 0; c < candidates.cols(); ++c) {
    const Eigen::Vector3d u = candidates.col(c);
    bool clear = true;
    for (const auto& row : rows) clear = clear && u.dot(row) < std::cos(kLatticeRowClearance);
    if (!clear) continue;
    double score = 0;  // the largest |cos| between a pole and a face normal: smaller is farther
    for (const auto& f : faces) score = std::max(score, std::abs(u.dot(f.normal)));
    if (score < best_score) best_score = score, best = u;
  }
  return best;
}

bool inside_faces(const Eigen::Vector3d& x, const std::vector<Face>& faces, double margin_m) {
  for (const auto& f : faces)
    if (x.dot(f.normal) >= f.distance_m - margin_m) return false;
  return true;
}

// Points binned on a grid of spacing `range`: the nearest within range of a query looks at 27 bins, not
// at every point (a face of a fine wall holds tens of thousands: all pairs took minutes; issue 51).
class NearestWithin {
 public:
  NearestWithin(const std::vector<int>& ids, const std::function<Eigen::Vector3d(int)>& at, double range_m)
      : at_(at), range_m_(range_m) {
    for (int id : ids) bins_[key(bin_of(at(id)))].push_back(id);
  }
  // The point nearest x closer than the range (ties: the smallest id, as a scan in id order finds),
  // with its squared distance; -1 if none.
  std::pair<int, double> nearest(const Eigen::Vector3d& x) const {
    int best = -1;
    double best2 = range_m_ * range_m_;
    const std::array<std::int64_t, 3> c = bin_of(x);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto bin = bins_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (bin == bins_.end()) continue;
          for (int id : bin->second) {
            const double r2 = (at_(id) - x).squaredNorm();
            if (r2 < best2 || (r2 == best2 && best >= 0 && id < best)) best2 = r2, best = id;
          }
        }
    return {best, best2};
  }

 private:
  std::array<std::int64_t, 3> bin_of(const Eigen::Vector3d& x) const {
    return {static_cast<std::int64_t>(std::floor(x.x() / range_m_)), static_cast<std::int64_t>(std::floor(x.y() / range_m_)),
            static_cast<std::int64_t>(std::floor(x.z() / range_m_))};
  }
  static std::int64_t key(const std::array<std::int64_t, 3>& c) {  // bins of one tissue: 2^21 a side is ample
    return ((c[0] & 0x1FFFFF) << 42) | ((c[1] & 0x1FFFFF) << 21) | (c[2] & 0x1FFFFF);
  }
  std::function<Eigen::Vector3d(int)> at_;
  double range_m_;
  std::unordered_map<std::int64_t, std::vector<int>> bins_;
};

// Facing wall particles of cells a and b bonded: each particle near the face takes its nearest
// partner across it, if within range; pairs found from both sides count once.
void bond_faces(const Tissue& t, int a, int b, const Face& face, double gap_m, double range_m,
                std::vector<LamellaBond>& bonds) {
  const auto near_face = [&](int cell, const Eigen::Vector3d& normal, double distance) {
    std::vector<int> near;
    for (Eigen::Index k = t.cells.wall[cell]; k < t.cells.wall[cell + 1]; ++k)
      if ((t.wall_x.col(k) - t.centre_m[cell]).dot(normal) > distance - range_m) near.push_back(static_cast<int>(k));
    return near;
  };
  const double between = (t.centre_m[b] + face.image - t.centre_m[a]).norm();
  const std::vector<int> side_a = near_face(a, face.normal, face.distance_m);
  const std::vector<int> side_b = near_face(b, -face.normal, between - face.distance_m - gap_m);  // b's own face
  std::vector<LamellaBond> found;
  // a's particles where they are, b's in the image that faces a
  const auto at_a = [&](int i) -> Eigen::Vector3d { return t.wall_x.col(i); };
  const auto at_b = [&](int j) -> Eigen::Vector3d { return t.wall_x.col(j) + face.image; };
  const NearestWithin near_a(side_a, at_a, range_m), near_b(side_b, at_b, range_m);
  const auto bond = [&](int from, const NearestWithin& others, const Eigen::Vector3d& x) {
    const auto [best, best2] = others.nearest(x);
    if (best >= 0) found.push_back({std::min(from, best), std::max(from, best), std::sqrt(best2)});
  };
  for (int i : side_a) bond(i, near_b, at_a(i));
  for (int j : side_b) bond(j, near_a, at_b(j));
  const auto pair_of = [](const LamellaBond& bond) { return std::make_pair(bond.a, bond.b); };
  std::sort(found.begin(), found.end(), [&](const auto& x, const auto& y) { return pair_of(x) < pair_of(y); });
  found.erase(std::unique(found.begin(), found.end(), [&](const auto& x, const auto& y) { return pair_of(x) == pair_of(y); }),
              found.end());
  bonds.insert(bonds.end(), found.begin(), found.end());
}

}  // namespace

namespace {
// The cell of each particle, from each cell's first particle (first.back(): the particle count).
std::vector<int> cell_of(const std::vector<Eigen::Index>& first) {
  std::vector<int> cell(static_cast<std::size_t>(first.back()));
  for (std::size_t c = 0; c + 1 < first.size(); ++c)
    std::fill(cell.begin() + first[c], cell.begin() + first[c + 1], static_cast<int>(c));
  return cell;
}
}  // namespace

std::vector<int> CellRanges::cell_of_fluid() const { return cell_of(fluid); }
int CellRanges::layers() const { return layer.empty() ? 1 : *std::max_element(layer.begin(), layer.end()) + 1; }
std::vector<int> CellRanges::cell_of_wall() const { return cell_of(wall); }

Tissue build_tissue(const Params& p) {
  if (!p.r0_m || !p.fill_gap_m || !p.h0_m || !p.wall_gap_m)
    throw std::logic_error("build_tissue: the case's derived parameters are unresolved (resolve_derived_geometry)");
  const double gap = *p.wall_gap_m;
  const double centre_distance = p.centre_distance_over_diameter * p.diameter_m;
  const std::vector<Eigen::Vector3d> centres = lattice_centres(p, centre_distance);
  const std::vector<double> radii = cell_radii(p, centres.size());

  Tissue t;
  t.mesh.cell_triangles = {0};
  t.wall_mass_kg = wall_particle_mass_kg(p);
  t.fluid_spacing_m = fluid_spacing_m(p);
  t.centre_m = centres;
  t.box = lattice_period(p, centre_distance);
  t.wall_particle_area_m2 = M_PI * p.diameter_m * p.diameter_m / static_cast<double>(p.n_wall);
  std::vector<Eigen::Matrix3Xd> walls, fluids;
  std::vector<double> fluid_masses;
  for (int c = 0; c < static_cast<int>(centres.size()); ++c) {
    const double rc = radii[c];
    const std::vector<Face> faces = faces_of(c, centres, radii, gap, t.box);
    CellShape shape{rc, spiral_axis(faces), nullptr, nullptr};
    if (!faces.empty()) {  // flattened where it meets a neighbour; its fluid kept the fill gap from the faces
      shape.onto_faces = [&](const Eigen::Vector3d& x) { return onto_faces(x, rc, faces); };
      shape.holds_fluid = [&](const Eigen::Vector3d& x) { return inside_faces(x, faces, *p.fill_gap_m); };
    }
    Cell cell = build_cell(p, shape, t.fluid_spacing_m);
    if (cell.fluid_x.cols() == 0 && p.fluid_model != kCavityFluid) {  // the fill gap (or the faces pressed flat) left no lattice point inside
      std::ostringstream msg;
      msg << "cell.fill_gap_um = " << *p.fill_gap_m * 1e6 << ": cell " << c << " (radius " << rc * 1e6
          << " um, its faces at tissue.centre_distance_over_diameter = " << p.centre_distance_over_diameter
          << " and tissue.wall_gap_um = " << gap * 1e6
          << ") holds no fluid particle farther than that from its wall; give smaller gaps";
      throw InputError(msg.str());
    }
    fluid_masses.push_back(cell.fluid_mass_kg);
    WallMesh& mesh = cell.mesh;
    const int first_triangle = static_cast<int>(t.mesh.triangles.size());
    for (auto& tri : mesh.triangles)
      for (int& v : tri) v += static_cast<int>(t.cells.wall.back());
    for (auto& b : mesh.bonds)
      for (int& v : b) v += static_cast<int>(t.cells.wall.back());
    for (auto& h : mesh.hinges) {
      for (int* v : {&h.a, &h.b, &h.c, &h.d}) *v += static_cast<int>(t.cells.wall.back());
      h.t1 += first_triangle;
      h.t2 += first_triangle;
    }
    t.mesh.triangles.insert(t.mesh.triangles.end(), mesh.triangles.begin(), mesh.triangles.end());
    t.mesh.bonds.insert(t.mesh.bonds.end(), mesh.bonds.begin(), mesh.bonds.end());
    t.mesh.rest_length_m.insert(t.mesh.rest_length_m.end(), mesh.rest_length_m.begin(), mesh.rest_length_m.end());
    t.mesh.hinges.insert(t.mesh.hinges.end(), mesh.hinges.begin(), mesh.hinges.end());
    t.cells.wall.push_back(t.cells.wall.back() + cell.wall_x.cols());
    t.cells.layer.push_back(static_cast<int>(c / (p.cells_x * p.cells_y)));  // lattice_centres: layer by layer
    t.cells.fluid.push_back(t.cells.fluid.back() + cell.fluid_x.cols());
    t.mesh.cell_triangles.push_back(static_cast<int>(t.mesh.triangles.size()));
    walls.push_back(cell.wall_x.colwise() + centres[c]);
    fluids.push_back(cell.fluid_x.colwise() + centres[c]);
  }
  t.wall_x.resize(3, t.cells.wall.back());
  t.fluid_x.resize(3, t.cells.fluid.back());
  t.fluid_mass_kg.resize(t.cells.fluid.back());
  for (int c = 0; c < t.cells.count(); ++c) {
    t.wall_x.middleCols(t.cells.wall[c], t.cells.wall_count(c)) = walls[c];
    t.fluid_x.middleCols(t.cells.fluid[c], t.cells.fluid_count(c)) = fluids[c];
    t.fluid_mass_kg.segment(t.cells.fluid[c], t.cells.fluid_count(c)).setConstant(fluid_masses[c]);
  }
  for (int a = 0; a < t.cells.count(); ++a)  // each face once: from the lower-numbered of its two cells
    for (const Face& face : faces_of(a, centres, radii, gap, t.box))
      if (face.neighbour > a) bond_faces(t, a, face.neighbour, face, gap, kLamellaRangeOverGap * gap, t.lamella);
  return t;
}

}  // namespace cellsim
