#include "bending.hpp"

#include <numeric>

#include <Eigen/Geometry>

namespace cellsim {

Bending::Bending(const WallMesh& mesh, double bending_stiffness_J) : mesh_(mesh) {
  const auto& l0 = mesh.rest_length_m;
  const double mean_l0 = l0.empty() ? 1.0 : std::accumulate(l0.begin(), l0.end(), 0.0) / static_cast<double>(l0.size());
  // Hinges are built from the bonds in the same order, so hinge n has bond n's rest length.
  weight_.reserve(mesh.hinges.size());
  for (std::size_t n = 0; n < mesh.hinges.size(); ++n) weight_.push_back(bending_stiffness_J * l0[n] / mean_l0);
}

double Bending::energy(const Eigen::Matrix3Xd& x) const {
  TriangleNormals normals;
  compute_triangle_normals(x, mesh_, normals);
  double e = 0;
  for (std::size_t n = 0; n < mesh_.hinges.size(); ++n) {
    const Hinge& h = mesh_.hinges[n];
    const double c = normals.N.col(h.t1).dot(normals.N.col(h.t2)) * normals.inv_norm[h.t1] * normals.inv_norm[h.t2];
    e += 0.5 * weight_[n] * (1.0 - c) / (1.0 + c);
  }
  return e;
}

void Bending::add_forces(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& force) const {
  TriangleNormals normals;
  compute_triangle_normals(x, mesh_, normals);
  add_forces(x, normals, force);
}

void Bending::add_forces(const Eigen::Matrix3Xd& x, const TriangleNormals& normals, Eigen::Matrix3Xd& force) const {
  // d(n1.n2) = p1 . dN1 + p2 . dN2, p1 = (n2 - c n1)/|N1|, p2 = (n1 - c n2)/|N2|, and
  // dE/dc = -(k_b L_n / 2) * 2 / (1 + c)^2, so F = k_b L_n / (1 + c)^2 grad c. The force is linear
  // in p, so each hinge adds its weighted p to its two triangles, and each triangle (u, v, w) then
  // turns the sum P into vertex forces once: d(P . N)/du = (v - w) x P, i.e. (next - previous) x P.
  auto& P = triangle_sum_;
  P.setZero(3, normals.N.cols());
  for (std::size_t n = 0; n < mesh_.hinges.size(); ++n) {
    const Hinge& h = mesh_.hinges[n];
    const Eigen::Vector3d n1 = normals.N.col(h.t1) * normals.inv_norm[h.t1];
    const Eigen::Vector3d n2 = normals.N.col(h.t2) * normals.inv_norm[h.t2];
    const double c = n1.dot(n2);
    const double scale = weight_[n] / ((1.0 + c) * (1.0 + c));
    P.col(h.t1) += (scale * normals.inv_norm[h.t1]) * (n2 - c * n1);
    P.col(h.t2) += (scale * normals.inv_norm[h.t2]) * (n1 - c * n2);
  }
  for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
    const auto& tri = mesh_.triangles[t];
    const Eigen::Vector3d p = P.col(static_cast<Eigen::Index>(t));
    const Eigen::Vector3d u = x.col(tri[0]), v = x.col(tri[1]), w = x.col(tri[2]);
    force.col(tri[0]) += (v - w).cross(p);
    force.col(tri[1]) += (w - u).cross(p);
    force.col(tri[2]) += (u - v).cross(p);
  }
}

}  // namespace cellsim
