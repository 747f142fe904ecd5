#include "containment.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cellsim {
namespace {

// 2-D edge function: > 0 when p is left of a->b. Ties are broken by a top-left rule so a ray
// through a shared edge or vertex counts exactly one of the triangles that meet there.
bool covers(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& p) {
  const auto edge = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v, const Eigen::Vector2d& q) {
    const double e = (v.x() - u.x()) * (q.y() - u.y()) - (v.y() - u.y()) * (q.x() - u.x());
    if (e != 0) return e > 0;
    return (v.y() > u.y()) || (v.y() == u.y() && v.x() < u.x());  // top-left tie rule
  };
  const double orient = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  if (orient == 0) return false;  // edge-on triangle: no area under the ray
  if (orient > 0) return edge(a, b, p) && edge(b, c, p) && edge(c, a, p);
  return edge(a, c, p) && edge(c, b, p) && edge(b, a, p);
}

}  // namespace

int first_particle_outside(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const WallMesh& mesh) {
  if (fluid_x.cols() == 0) return -1;
  const Eigen::Vector2d lo = wall_x.topRows<2>().rowwise().minCoeff(), hi = wall_x.topRows<2>().rowwise().maxCoeff();
  const int bins = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(mesh.triangles.size()) / 4.0)));
  const Eigen::Vector2d span = (hi - lo).cwiseMax(1e-30);
  const auto bin_of = [&](double v, int d) {
    return std::clamp(static_cast<int>((v - lo[d]) / span[d] * bins), 0, bins - 1);
  };
  std::vector<std::vector<int>> bin_triangles(static_cast<std::size_t>(bins * bins));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    Eigen::Vector2d tlo = wall_x.col(tri[0]).head<2>(), thi = tlo;
    for (int v : tri) {
      tlo = tlo.cwiseMin(wall_x.col(v).head<2>());
      thi = thi.cwiseMax(wall_x.col(v).head<2>());
    }
    for (int bx = bin_of(tlo.x(), 0); bx <= bin_of(thi.x(), 0); ++bx)
      for (int by = bin_of(tlo.y(), 1); by <= bin_of(thi.y(), 1); ++by)
        bin_triangles[static_cast<std::size_t>(by * bins + bx)].push_back(static_cast<int>(t));
  }
  for (Eigen::Index i = 0; i < fluid_x.cols(); ++i) {
    const Eigen::Vector3d p = fluid_x.col(i);
    if (p.x() < lo.x() || p.x() > hi.x() || p.y() < lo.y() || p.y() > hi.y()) return static_cast<int>(i);
    int crossings = 0;
    for (int t : bin_triangles[static_cast<std::size_t>(bin_of(p.y(), 1) * bins + bin_of(p.x(), 0))]) {
      const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
      const Eigen::Vector3d a = wall_x.col(tri[0]), b = wall_x.col(tri[1]), c = wall_x.col(tri[2]);
      if (!covers(a.head<2>(), b.head<2>(), c.head<2>(), p.head<2>())) continue;
      // Height of the triangle's plane above p's xy position.
      const Eigen::Vector3d n = (b - a).cross(c - a);
      const double z_plane = a.z() - (n.x() * (p.x() - a.x()) + n.y() * (p.y() - a.y())) / n.z();
      if (z_plane > p.z()) ++crossings;
    }
    if (crossings % 2 == 0) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace cellsim
