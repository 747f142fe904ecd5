#include "geometry/containment.hpp"

#include <algorithm>
#include <cmath>

namespace cellsim {
namespace {

// 2-D edge function: > 0 when p is left of a->b. Ties are broken by a top-left rule so a ray
// through a shared edge or vertex counts exactly one of the triangles that meet there.
bool covers(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& p) {
  const auto edge = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v, const Eigen::Vector2d& q) {
    // At q = v the two products are equal, but a fused multiply-add (which the compiler may use)
    // leaves their rounding error instead of 0, and the tie rule would not apply: say 0 outright.
    const double e = q == v ? 0.0 : (v.x() - u.x()) * (q.y() - u.y()) - (v.y() - u.y()) * (q.x() - u.x());
    if (e != 0) return e > 0;
    return (v.y() > u.y()) || (v.y() == u.y() && v.x() < u.x());  // top-left tie rule
  };
  const double orient = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  if (orient == 0) return false;  // edge-on triangle: no area under the ray
  if (orient > 0) return edge(a, b, p) && edge(b, c, p) && edge(c, a, p);
  return edge(a, c, p) && edge(c, b, p) && edge(b, a, p);
}

}  // namespace

ClosedSurface::ClosedSurface(const Eigen::Matrix3Xd& wall_x, const WallMesh& mesh, int cell)
    : wall_x_(wall_x), mesh_(mesh) {
  const int first = mesh.cell_triangles[cell], last = mesh.cell_triangles[cell + 1];
  lo_ = hi_ = wall_x.col(mesh.triangles[first][0]);
  for (int t = first; t < last; ++t)
    for (int v : mesh.triangles[t]) {
      lo_ = lo_.cwiseMin(wall_x.col(v));
      hi_ = hi_.cwiseMax(wall_x.col(v));
    }
  bins_ = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(last - first) / 4.0)));
  bin_triangles_.resize(static_cast<std::size_t>(bins_ * bins_));
  for (int t = first; t < last; ++t) {
    const auto& tri = mesh.triangles[t];
    Eigen::Vector2d tlo = wall_x.col(tri[0]).head<2>(), thi = tlo;
    for (int v : tri) {
      tlo = tlo.cwiseMin(wall_x.col(v).head<2>());
      thi = thi.cwiseMax(wall_x.col(v).head<2>());
    }
    for (int bx = bin_of(tlo.x(), 0); bx <= bin_of(thi.x(), 0); ++bx)
      for (int by = bin_of(tlo.y(), 1); by <= bin_of(thi.y(), 1); ++by)
        bin_triangles_[static_cast<std::size_t>(by * bins_ + bx)].push_back(t);
  }
}

int ClosedSurface::bin_of(double v, int d) const {
  const double span = std::max(hi_[d] - lo_[d], 1e-30);
  return std::clamp(static_cast<int>((v - lo_[d]) / span * bins_), 0, bins_ - 1);
}

bool ClosedSurface::box_overlaps(const ClosedSurface& other) const {
  return (lo_.array() <= other.hi_.array()).all() && (other.lo_.array() <= hi_.array()).all();
}

bool ClosedSurface::contains(const Eigen::Vector3d& p) const {
  if ((p.array() < lo_.array()).any() || (p.array() > hi_.array()).any()) return false;  // outside the box
  int crossings = 0;
  for (int t : bin_triangles_[static_cast<std::size_t>(bin_of(p.y(), 1) * bins_ + bin_of(p.x(), 0))]) {
    const auto& tri = mesh_.triangles[static_cast<std::size_t>(t)];
    const Eigen::Vector3d a = wall_x_.col(tri[0]), b = wall_x_.col(tri[1]), c = wall_x_.col(tri[2]);
    if (!covers(a.head<2>(), b.head<2>(), c.head<2>(), p.head<2>())) continue;
    // Height of the triangle's plane above p's xy position.
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double z_plane = a.z() - (n.x() * (p.x() - a.x()) + n.y() * (p.y() - a.y())) / n.z();
    if (z_plane > p.z()) ++crossings;
  }
  return crossings % 2 == 1;
}

int first_particle_outside(const Eigen::Matrix3Xd& points, Eigen::Index begin, Eigen::Index end,
                           const ClosedSurface& wall) {
  for (Eigen::Index i = begin; i < end; ++i)
    if (!wall.contains(points.col(i))) return static_cast<int>(i);
  return -1;
}

int first_particle_outside(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const WallMesh& mesh) {
  if (fluid_x.cols() == 0) return -1;
  return first_particle_outside(fluid_x, 0, fluid_x.cols(), ClosedSurface(wall_x, mesh, 0));
}

}  // namespace cellsim
