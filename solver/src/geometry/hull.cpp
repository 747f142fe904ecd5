#include "geometry/hull.hpp"

#include <cmath>
#include <cstdio>
#include <string>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include "core/errors.hpp"

namespace cellsim {

std::vector<std::array<int, 3>> convex_hull_triangles(const Eigen::Matrix3Xd& points) {
  const int n = static_cast<int>(points.cols());
  if (n < 4) throw InputError("a closed wall needs at least 4 points, got " + std::to_string(n));
  std::vector<coordT> coords(points.data(), points.data() + 3 * n);  // column-major = xyz per point
  const Eigen::Vector3d centroid = points.rowwise().mean();

  qhT qh_storage;
  qhT* qh = &qh_storage;
  qh_zero(qh, stderr);
  char options[] = "qhull Qt";  // Qt: triangulated output, so every facet is a triangle
  const int exitcode = qh_new_qhull(qh, 3, n, coords.data(), False, options, nullptr, stderr);

  std::vector<std::array<int, 3>> triangles;
  std::vector<char> used(static_cast<std::size_t>(n), 0);
  if (exitcode == 0) {
    facetT* facet;
    FORALLfacets {
      std::array<int, 3> tri{};
      int k = 0;
      vertexT *vertex, **vertexp;
      FOREACHvertex_(facet->vertices) {
        if (k < 3) tri[static_cast<std::size_t>(k)] = qh_pointid(qh, vertex->point);
        ++k;
      }
      if (k != 3) continue;
      const Eigen::Vector3d a = points.col(tri[0]), b = points.col(tri[1]), c = points.col(tri[2]);
      if ((b - a).cross(c - a).dot(a - centroid) < 0) std::swap(tri[1], tri[2]);  // outward normal
      for (int v : tri) used[static_cast<std::size_t>(v)] = 1;
      triangles.push_back(tri);
    }
  }
  int curlong = 0, totlong = 0;
  qh_freeqhull(qh, !qh_ALL);
  qh_memfreeshort(qh, &curlong, &totlong);
  if (exitcode != 0) throw InputError("Qhull could not triangulate the wall points (exit code " +
                                      std::to_string(exitcode) + ")");
  for (int i = 0; i < n; ++i)
    if (!used[static_cast<std::size_t>(i)])
      throw InputError("wall point " + std::to_string(i) + " is not on the convex hull; use more or fewer wall points");
  return triangles;
}

namespace {
// Qhull's hull of points (dim x n, column-major), measured: its volume (area in 2-D), NaN if it fails.
double hull_measure(const double* data, int dim, int n) {
  if (n <= dim) return 0.0;
  std::vector<coordT> coords(data, data + dim * n);
  qhT qh_storage;
  qhT* qh = &qh_storage;
  qh_zero(qh, stderr);
  char options[] = "qhull";
  const int exitcode = qh_new_qhull(qh, dim, n, coords.data(), False, options, nullptr, stderr);
  if (exitcode == 0) qh_getarea(qh, qh->facet_list);  // sums the facets' areas and volumes
  const double measure = exitcode == 0 ? qh->totvol : std::nan("");
  int curlong = 0, totlong = 0;
  qh_freeqhull(qh, !qh_ALL);
  qh_memfreeshort(qh, &curlong, &totlong);
  return measure;
}
}  // namespace

double convex_hull_volume(const Eigen::Matrix3Xd& points) {
  return hull_measure(points.data(), 3, static_cast<int>(points.cols()));
}

double convex_hull_area_2d(const Eigen::Matrix2Xd& points) {
  return hull_measure(points.data(), 2, static_cast<int>(points.cols()));
}

}  // namespace cellsim
