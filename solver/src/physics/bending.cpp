#include "physics/bending.hpp"

#include <array>
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

void Bending::add_gauss_newton_stiffness(const Eigen::Matrix3Xd& x, FarCorners far_corners, BlockStiffness& K) const {
  const bool on_bonds = far_corners == FarCorners::OnBonds;
  for (std::size_t n = 0; n < mesh_.hinges.size(); ++n) {
    const Hinge& h = mesh_.hinges[n];
    const Eigen::Vector3d e = x.col(h.b) - x.col(h.a);
    const double length2 = e.squaredNorm();
    const Eigen::Vector3d N1 = e.cross(x.col(h.c) - x.col(h.a));  // triangle (a, b, c)
    const Eigen::Vector3d N2 = (-e).cross(x.col(h.d) - x.col(h.b));  // triangle (b, a, d)
    // Lifting c by dz along n1 turns its triangle by dz / (its height over the edge) = dz |e| / |N1|; a and
    // b share the turn by where c's foot falls on the edge (s_c from a).
    const Eigen::Vector3d g_c = std::sqrt(length2) / N1.squaredNorm() * N1;
    const Eigen::Vector3d g_d = std::sqrt(length2) / N2.squaredNorm() * N2;
    const double s_c = (x.col(h.c) - x.col(h.a)).dot(e) / length2, s_d = (x.col(h.d) - x.col(h.a)).dot(e) / length2;
    const std::array<Eigen::Vector3d, 4> g = {-(1 - s_c) * g_c - (1 - s_d) * g_d, -s_c * g_c - s_d * g_d, g_c, g_d};
    const std::array<int, 4> vertex = {h.a, h.b, h.c, h.d};
    // Eq 20's hinge, (w/2) tan^2(theta/2) with w = k_b L_n: its d2/dtheta2 = (w/4)(1 + t^2)(1 + 3 t^2),
    // t^2 = (1 - cos theta)/(1 + cos theta).
    const double cos_theta = N1.normalized().dot(N2.normalized());
    const double t2 = (1 - cos_theta) / (1 + cos_theta);
    const double curvature = weight_[n] / 4 * (1 + t2) * (1 + 3 * t2);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const bool far_pair = i >= 2 && j >= 2;  // c-c, c-d, d-c, d-d: (g_c - g_d)(g_c - g_d)^T cancels c-d
        if (on_bonds && far_pair && i != j) continue;
        const double scale = on_bonds && far_pair ? 2 * curvature : curvature;
        const auto gi = static_cast<std::size_t>(i), gj = static_cast<std::size_t>(j);
        K.add(vertex[gi], vertex[gj], scale * g[gi] * g[gj].transpose());
      }
  }
}

void Bending::add_forces(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& force) const {
  TriangleNormals normals;
  compute_triangle_normals(x, mesh_, normals);
  add_forces(x, normals, 1, force);
}

void Bending::add_forces(const Eigen::Matrix3Xd& x, const TriangleNormals& normals, int threads,
                         Eigen::Matrix3Xd& force) const {
  // d(n1.n2) = p1 . dN1 + p2 . dN2, p1 = (n2 - c n1)/|N1|, p2 = (n1 - c n2)/|N2|, and
  // dE/dc = -(k_b L_n / 2) * 2 / (1 + c)^2, so F = k_b L_n / (1 + c)^2 grad c. The force is linear
  // in p, so each hinge adds its weighted p to its two triangles, and each triangle (u, v, w) then
  // turns the sum P into vertex forces once: d(P . N)/du = (v - w) x P, i.e. (next - previous) x P.
  const auto n_triangles = static_cast<int>(mesh_.triangles.size());
  triangle_sum_.resize(3, n_triangles);
  const auto& hinge_spans = hinge_spans_.for_threads(
      threads, n_triangles, static_cast<Eigen::Index>(mesh_.hinges.size()), [&](Eigen::Index n) {
        const Hinge& h = mesh_.hinges[static_cast<std::size_t>(n)];
        return std::array<int, 2>{h.t1, h.t2};
      });
  for_owned_spans(threads, hinge_spans, [&](int, const OwnedSpan& span) {
    triangle_sum_.middleCols(span.target_begin, span.target_end - span.target_begin).setZero();
    with_all_or_some(span, [&](auto all) { add_hinges(all, normals, span, triangle_sum_); });
  });
  const auto& triangle_spans = triangle_spans_.for_threads(
      threads, static_cast<int>(x.cols()), n_triangles,
      [&](Eigen::Index t) { return mesh_.triangles[static_cast<std::size_t>(t)]; });
  for_owned_spans(threads, triangle_spans,
                  [&](int, const OwnedSpan& span) {
                    with_all_or_some(span, [&](auto all) { add_triangle_forces(all, x, triangle_sum_, span, force); });
                  });
}

// The span's hinges: weighted p of each to the triangles' sums P it owns.
template <class All>
void Bending::add_hinges(All, const TriangleNormals& normals, const OwnedSpan& span, Eigen::Matrix3Xd& P) const {
  for (Eigen::Index n = span.item_begin; n < span.item_end; ++n) {
    const Hinge& h = mesh_.hinges[static_cast<std::size_t>(n)];
    const bool owns_t1 = All::value || span.owns(h.t1), owns_t2 = All::value || span.owns(h.t2);
    if (!owns_t1 && !owns_t2) continue;
    const Eigen::Vector3d n1 = normals.N.col(h.t1) * normals.inv_norm[h.t1];
    const Eigen::Vector3d n2 = normals.N.col(h.t2) * normals.inv_norm[h.t2];
    const double c = n1.dot(n2);
    const double scale = weight_[static_cast<std::size_t>(n)] / ((1.0 + c) * (1.0 + c));
    if (owns_t1) P.col(h.t1) += (scale * normals.inv_norm[h.t1]) * (n2 - c * n1);
    if (owns_t2) P.col(h.t2) += (scale * normals.inv_norm[h.t2]) * (n1 - c * n2);
  }
}

// The span's triangles: P into forces on the corners it owns.
template <class All>
void Bending::add_triangle_forces(All, const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& P, const OwnedSpan& span,
                                  Eigen::Matrix3Xd& force) const {
  for (Eigen::Index t = span.item_begin; t < span.item_end; ++t) {
    const auto& tri = mesh_.triangles[static_cast<std::size_t>(t)];
    const bool owns_u = All::value || span.owns(tri[0]), owns_v = All::value || span.owns(tri[1]),
               owns_w = All::value || span.owns(tri[2]);
    if (!owns_u && !owns_v && !owns_w) continue;
    const Eigen::Vector3d p = P.col(t);
    const Eigen::Vector3d u = x.col(tri[0]), v = x.col(tri[1]), w = x.col(tri[2]);
    if (owns_u) force.col(tri[0]) += (v - w).cross(p);
    if (owns_v) force.col(tri[1]) += (w - u).cross(p);
    if (owns_w) force.col(tri[2]) += (u - v).cross(p);
  }
}

}  // namespace cellsim
