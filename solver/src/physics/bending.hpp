#pragma once
// Wall bending, Eq 20: E_b = (k_b/2) sum_hinges L_n (1 - n1.n2)/(1 + n1.n2), n1 and n2 the unit
// normals of the two triangles sharing a hinge edge, L_n = l0_n / mean(l0) (the edge's rest length,
// a fixed geometric weight). Forces are -grad E_b, derived analytically from dot and cross products.
#include <vector>

#include <Eigen/Core>

#include "geometry/block_stiffness.hpp"
#include "geometry/surface.hpp"  // the triangle normals, computed once a step
#include "geometry/wall_mesh.hpp"
#include "parallel/owned_spans.hpp"

namespace cellsim {

class Bending {
 public:
  Bending(const WallMesh& mesh, double bending_stiffness_J);

  double energy(const Eigen::Matrix3Xd& x) const;
  // Adds -grad E_b to force (3 x N_w), with the triangle normals of x.
  void add_forces(const Eigen::Matrix3Xd& x, const TriangleNormals& normals, int threads,
                  Eigen::Matrix3Xd& force) const;
  void add_forces(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& force) const;  // computes the normals

  // The Gauss-Newton part of Eq 20's Hessian (3N x 3N): per hinge E_b''(theta) g g^T, g the gradient of
  // the hinge's angle theta, E_b = (k_b L_n / 2) tan^2(theta/2); positive semi-definite, without
  // E_b'(theta) times theta's own Hessian, so exact on a flat sheet. A hinge couples its two far corners
  // c and d, which no bond joins. OnBonds adds E_b'' (g_c - g_d)(g_c - g_d)^T, which cancels that coupling:
  // a matrix above the exact one, with the bonds' sparsity, so that a factor of it beside the springs
  // fills no more than theirs (engine/newton_preconditioner.hpp).
  enum class FarCorners { Coupled, OnBonds };
  // Adds it to K, whose pattern holds the bonds (and, for Coupled, every hinge's c-d pair).
  void add_gauss_newton_stiffness(const Eigen::Matrix3Xd& x, FarCorners far_corners, BlockStiffness& K) const;

 private:
  template <class All>  // std::true_type: the span owns every target (owned_spans.hpp)
  void add_hinges(All, const TriangleNormals& normals, const OwnedSpan& span, Eigen::Matrix3Xd& P) const;
  template <class All>
  void add_triangle_forces(All, const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& P, const OwnedSpan& span,
                           Eigen::Matrix3Xd& force) const;

  const WallMesh& mesh_;
  std::vector<double> weight_;  // k_b L_n per hinge
  mutable Eigen::Matrix3Xd triangle_sum_;  // scratch of add_forces: weighted p summed per triangle
  // Each thread's triangles and particles, and the hinges and triangles that touch them (owned_spans.hpp).
  mutable OwnedSpans hinge_spans_, triangle_spans_;
};

}  // namespace cellsim
