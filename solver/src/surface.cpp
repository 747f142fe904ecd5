#include "surface.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace cellsim {

void compute_triangle_normals(const Eigen::Matrix3Xd& x, const WallMesh& mesh, TriangleNormals& out) {
  const auto n = static_cast<Eigen::Index>(mesh.triangles.size());
  out.N.resize(3, n);
  out.inv_norm.resize(n);
  for (Eigen::Index t = 0; t < n; ++t) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    const Eigen::Vector3d a = x.col(tri[0]);
    out.N.col(t) = (x.col(tri[1]) - a).cross(x.col(tri[2]) - a);
  }
  out.norm = out.N.colwise().norm().transpose();  // packed square roots and divisions
  out.inv_norm = out.norm.cwiseInverse();
}

void WallSurface::update(const Eigen::Matrix3Xd& x, const WallMesh& mesh) {
  compute_triangle_normals(x, mesh, triangles);
  vertex_normal.setZero(3, x.cols());
  double six_volume = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d n = triangles.N.col(static_cast<Eigen::Index>(t));
    six_volume += x.col(tri[0]).dot(n);  // a . (b x c) = a . ((b - a) x (c - a))
    for (int v : tri) vertex_normal.col(v) += n;
  }
  area_m2 = 0.5 * triangles.norm.sum();
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
