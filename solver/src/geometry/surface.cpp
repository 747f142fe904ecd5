#include "geometry/surface.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "parallel/threads.hpp"

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

// The span's triangles: their area normals added to the corners it owns; adds to six_volume[c] the
// six volumes of cell c's triangles whose first corner it owns (so each triangle counts once).
template <class All>
void add_to_vertex_normals(All, const Eigen::Matrix3Xd& x, const WallMesh& mesh, const Eigen::Matrix3Xd& N,
                           const OwnedSpan& span, Eigen::Matrix3Xd& vertex_normal, double* six_volume) {
  int cell = 0;
  while (mesh.cell_triangles[cell + 1] <= span.item_begin && cell + 1 < mesh.cells()) ++cell;
  double sum = 0;  // of the current cell: a register, not memory, in the inner loop
  for (Eigen::Index t = span.item_begin; t < span.item_end; ++t) {
    if (t >= mesh.cell_triangles[cell + 1]) {
      six_volume[cell] += sum;
      sum = 0;
      while (t >= mesh.cell_triangles[cell + 1]) ++cell;
    }
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    const Eigen::Vector3d n = N.col(t);
    if (All::value || span.owns(tri[0])) sum += x.col(tri[0]).dot(n);  // a . (b x c) = a . ((b - a) x (c - a))
    for (int v : tri)
      if (All::value || span.owns(v)) vertex_normal.col(v) += n;
  }
  six_volume[cell] += sum;
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
  const auto cells = static_cast<std::size_t>(mesh.cells());
  six_volume_.assign(static_cast<std::size_t>(threads) * cells, 0.0);
  const auto& spans = spans_.for_threads(threads, static_cast<int>(x.cols()), triangles.N.cols(), [&](Eigen::Index t) {
    return mesh.triangles[static_cast<std::size_t>(t)];
  });
  for_owned_spans(threads, spans, [&](int t, const OwnedSpan& span) {
    vertex_normal.middleCols(span.target_begin, span.target_end - span.target_begin).setZero();
    double* six_volume = six_volume_.data() + static_cast<std::size_t>(t) * cells;
    with_all_or_some(span, [&](auto all) {
      add_to_vertex_normals(all, x, mesh, triangles.N, span, vertex_normal, six_volume);
    });
  });
  cell_area_m2.resize(cells);
  cell_volume_m3.resize(cells);
  area_m2 = volume_m3 = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    const int first = mesh.cell_triangles[c];
    cell_area_m2[c] = 0.5 * triangles.norm.segment(first, mesh.cell_triangles[c + 1] - first).sum();
    double six_volume = 0;
    for (std::size_t t = 0; t < static_cast<std::size_t>(threads); ++t)
      six_volume += six_volume_[t * cells + c];  // threads in order
    cell_volume_m3[c] = six_volume / 6.0;
    area_m2 += cell_area_m2[c];
    volume_m3 += cell_volume_m3[c];
  }
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
