#include "surface.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "threads.hpp"

namespace cellsim {

namespace {

// Triangles [begin, end): area normals, |N| and 1 / |N| (packed square roots and divisions).
void triangle_normals(const Eigen::Matrix3Xd& x, const WallMesh& mesh, Eigen::Index begin, Eigen::Index end,
                      TriangleNormals& out) {
  for (Eigen::Index t = begin; t < end; ++t) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    const Eigen::Vector3d a = x.col(tri[0]);
    out.N.col(t) = (x.col(tri[1]) - a).cross(x.col(tri[2]) - a);
  }
  const Eigen::Index count = end - begin;
  out.norm.segment(begin, count) = out.N.middleCols(begin, count).colwise().norm().transpose();
  out.inv_norm.segment(begin, count) = out.norm.segment(begin, count).cwiseInverse();
}

// The span's triangles: their area normals added to the corners it owns; returns the six volumes of
// the triangles whose first corner it owns (each triangle counted once).
template <class All>
double add_to_vertex_normals(All, const Eigen::Matrix3Xd& x, const WallMesh& mesh, const Eigen::Matrix3Xd& N,
                             const OwnedSpan& span, Eigen::Matrix3Xd& vertex_normal) {
  double six_volume = 0;
  for (Eigen::Index t = span.item_begin; t < span.item_end; ++t) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    const Eigen::Vector3d n = N.col(t);
    if (All::value || span.owns(tri[0])) six_volume += x.col(tri[0]).dot(n);  // a . (b x c) = a . ((b - a) x (c - a))
    for (int v : tri)
      if (All::value || span.owns(v)) vertex_normal.col(v) += n;
  }
  return six_volume;
}

}  // namespace

void compute_triangle_normals(const Eigen::Matrix3Xd& x, const WallMesh& mesh, TriangleNormals& out, int threads) {
  const auto n = static_cast<Eigen::Index>(mesh.triangles.size());
  out.N.resize(3, n);
  out.norm.resize(n);
  out.inv_norm.resize(n);
  for_blocks(threads, n, [&](Eigen::Index begin, Eigen::Index end) { triangle_normals(x, mesh, begin, end, out); });
}

void WallSurface::update(const Eigen::Matrix3Xd& x, const WallMesh& mesh, int threads) {
  compute_triangle_normals(x, mesh, triangles, threads);
  vertex_normal.resize(3, x.cols());
  six_volume_.assign(static_cast<std::size_t>(threads), 0.0);
  const auto& spans = spans_.for_threads(threads, static_cast<int>(x.cols()), triangles.N.cols(), [&](Eigen::Index t) {
    return mesh.triangles[static_cast<std::size_t>(t)];
  });
  for_owned_spans(threads, spans, [&](int t, const OwnedSpan& span) {
    vertex_normal.middleCols(span.target_begin, span.target_end - span.target_begin).setZero();
    six_volume_[static_cast<std::size_t>(t)] = with_all_or_some(
        span, [&](auto all) { return add_to_vertex_normals(all, x, mesh, triangles.N, span, vertex_normal); });
  });
  area_m2 = 0.5 * triangles.norm.sum();
  double six_volume = 0;
  for (double part : six_volume_) six_volume += part;  // threads in order
  volume_m3 = six_volume / 6.0;
}

Eigen::VectorXd WallSurface::vertex_areas(const WallMesh& mesh) const {
  Eigen::VectorXd area = Eigen::VectorXd::Zero(vertex_normal.cols());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const double third = triangles.norm[static_cast<Eigen::Index>(t)] / 6.0;  // |N| is twice the area
    for (int v : mesh.triangles[t]) area[v] += third;
  }
  return area;
}

WallSurface wall_surface(const Eigen::Matrix3Xd& x, const WallMesh& mesh) {
  WallSurface s;
  s.update(x, mesh);
  return s;
}

double equivalent_diameter_m(double volume_m3) { return std::cbrt(6.0 * volume_m3 / M_PI); }

}  // namespace cellsim
