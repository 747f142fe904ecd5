#include "bending.hpp"

#include <numeric>

#include <Eigen/Geometry>

namespace cellsim {

Bending::Bending(const WallMesh& mesh, double bending_stiffness_J) : hinges_(mesh.hinges), k_b_(bending_stiffness_J) {
  const double mean_l0 = mesh.rest_length_m.empty()
                             ? 1.0
                             : std::accumulate(mesh.rest_length_m.begin(), mesh.rest_length_m.end(), 0.0) /
                                   static_cast<double>(mesh.rest_length_m.size());
  // Hinges are built from the bonds in the same order, so hinge n has bond n's rest length.
  weight_.reserve(hinges_.size());
  for (std::size_t n = 0; n < hinges_.size(); ++n) weight_.push_back(k_b_ * mesh.rest_length_m[n] / mean_l0);
}

double Bending::energy(const Eigen::Matrix3Xd& x) const {
  double e = 0;
  for (std::size_t n = 0; n < hinges_.size(); ++n) {
    const Hinge& h = hinges_[n];
    const Eigen::Vector3d n1 = (x.col(h.b) - x.col(h.a)).cross(x.col(h.c) - x.col(h.a)).normalized();
    const Eigen::Vector3d n2 = (x.col(h.a) - x.col(h.b)).cross(x.col(h.d) - x.col(h.b)).normalized();
    const double c = n1.dot(n2);
    e += 0.5 * weight_[n] * (1.0 - c) / (1.0 + c);
  }
  return e;
}

void Bending::add_forces(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& force) const {
  for (std::size_t n = 0; n < hinges_.size(); ++n) {
    const Hinge& h = hinges_[n];
    const Eigen::Vector3d xa = x.col(h.a), xb = x.col(h.b), xc = x.col(h.c), xd = x.col(h.d);
    // Triangle 1 = (a, b, c), triangle 2 = (b, a, d), both outward.
    const Eigen::Vector3d e1 = xb - xa, e2 = xc - xa;  // edges of triangle 1 from a
    const Eigen::Vector3d g1 = xa - xb, g2 = xd - xb;  // edges of triangle 2 from b
    const Eigen::Vector3d N1 = e1.cross(e2), N2 = g1.cross(g2);
    const double inv1 = 1.0 / N1.norm(), inv2 = 1.0 / N2.norm();
    const Eigen::Vector3d n1 = N1 * inv1, n2 = N2 * inv2;
    const double c = n1.dot(n2);
    // d(n1.n2) = p1 . dN1 / |N1| + p2 . dN2 / |N2|, with p1 = n2 - c n1 and p2 = n1 - c n2.
    const Eigen::Vector3d p1 = (n2 - c * n1) * inv1, p2 = (n1 - c * n2) * inv2;
    // For N = (u - o) x (w - o): grad_u = (w - o) x p, grad_w = p x (u - o), grad_o = -(grad_u + grad_w).
    const Eigen::Vector3d grad_b1 = e2.cross(p1), grad_c = p1.cross(e1);
    const Eigen::Vector3d grad_a2 = g2.cross(p2), grad_d = p2.cross(g1);
    // dE/dc = -(k_b L_n / 2) * 2 / (1 + c)^2, so F = -dE/dc grad c = k_b L_n / (1 + c)^2 grad c.
    const double scale = weight_[n] / ((1.0 + c) * (1.0 + c));
    force.col(h.a) += scale * (-(grad_b1 + grad_c) + grad_a2);
    force.col(h.b) += scale * (grad_b1 - (grad_a2 + grad_d));
    force.col(h.c) += scale * grad_c;
    force.col(h.d) += scale * grad_d;
  }
}

}  // namespace cellsim
