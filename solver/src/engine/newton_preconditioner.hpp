#pragma once
// The quasi-static Newton steps' preconditioner (quasi_static.hpp): the wall's stiffness without a
// tissue's contacts and the middle lamella, that is the springs (wall_stiffness.hpp), the bending's
// Gauss-Newton part on the bonds' pattern (bending.hpp), the follower stiffness of each closed cell's
// pressure, -P d2V/dx2, and each cell's volume spring k_c g_c g_c^T (g_c = dV_c/dx, k_c = -dP_c/dV_c;
// cavity_fluid.hpp). The sparse part is factored by CHOLMOD's supernodal Cholesky, its ordering found
// once a relaxation; where the wall folds and the matrix is not positive definite, a shift on its
// diagonal grows until it is. The volume springs join all of a cell's particles and would fill the
// factor: they enter by Sherman-Morrison, one rank a cell, exact because the sparse part joins no two
// cells.
#include <vector>

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "geometry/tissue.hpp"

namespace cellsim {

class NewtonPreconditioner {
 public:
  // stiffness: the sparse part, of the same pattern at every call (its ordering is found at the first);
  // volume_gradient: g stacked over the wall particles (each cell's on its own particles);
  // volume_stiffness_Pa_m3: k_c per cell.
  void factor(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& volume_gradient,
              const CellRanges& cells, const std::vector<double>& volume_stiffness_Pa_m3);
  // z = (the sparse part + the volume springs)^-1 r.
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const;
  // The diagonal shift the last factorization needed (0 where the matrix was positive definite) [N/m].
  double shift_N_m() const { return shift_N_m_; }

 private:
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> llt_;
  bool analyzed_ = false;
  double shift_N_m_ = 0;
  const CellRanges* cells_ = nullptr;
  Eigen::VectorXd g_, u_;         // g and u = (sparse part)^-1 g, each cell's on its own particles
  std::vector<double> scale_;     // per cell, 1 / (1 / k_c + g_c . u_c); 0 without a volume spring
};

}  // namespace cellsim
