#pragma once
// The quasi-static Newton steps' preconditioner (quasi_static.hpp): the wall's stiffness without a
// tissue's contacts and the middle lamella, that is the springs (wall_stiffness.hpp), the bending's
// Gauss-Newton part on the bonds' pattern (bending.hpp), the follower stiffness of each closed cell's
// pressure, -P d2V/dx2, and each cell's volume spring k_c g_c g_c^T (g_c = dV_c/dx, k_c = -dP_c/dV_c;
// cavity_fluid.hpp), and a tissue's contacts and middle lamella (cell_contact.hpp). The sparse part is
// factored by CHOLMOD's supernodal Cholesky, its ordering found once a relaxation; where the wall folds
// and the matrix is not positive definite, a shift on its diagonal grows until it is. The volume springs
// join all of a cell's particles and would fill the factor: they enter by the Woodbury identity. Where
// the sparse part joins no two cells, that is one rank a cell (Sherman-Morrison, a cell's rows alone);
// where a tissue's contacts join them, every cell's spring reaches every joined cell, and the update is
// of rank C, with A^-1 g_c for each of the C cells and a C x C capacitance matrix.
#include <vector>

#include <Eigen/CholmodSupport>
#include <Eigen/Core>
#include <Eigen/Cholesky>
#include <Eigen/SparseCore>

#include "geometry/tissue.hpp"

namespace cellsim {

class NewtonPreconditioner {
 public:
  // stiffness: the sparse part, of the same pattern at every call (its ordering is found at the first);
  // volume_gradient: g stacked over the wall particles (each cell's on its own particles);
  // volume_stiffness_Pa_m3: k_c per cell; cells_joined: whether the sparse part joins particles of
  // different cells (a tissue's contacts or lamella).
  void factor(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& volume_gradient,
              const CellRanges& cells, const std::vector<double>& volume_stiffness_Pa_m3, bool cells_joined = false);
  // z = (the sparse part + the volume springs)^-1 r.
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const;
  // The next factor() is of another pattern: its ordering is found again.
  void forget_ordering() { analyzed_ = false; }
  // The diagonal shift the last factorization needed (0 where the matrix was positive definite) [N/m].
  double shift_N_m() const { return shift_N_m_; }

 private:
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> llt_;
  bool analyzed_ = false;
  double shift_N_m_ = 0;
  const CellRanges* cells_ = nullptr;
  Eigen::VectorXd g_, u_;         // g and u = (sparse part)^-1 g, each cell's on its own particles
  std::vector<double> scale_;     // per cell, 1 / (1 / k_c + g_c . u_c); 0 without a volume spring
  // Cells joined: the cells with a volume spring, U's columns (sparse part)^-1 g_c for each of them, and
  // the capacitance diag(1 / k_c) + G^T U, factored.
  std::vector<int> sprung_;
  Eigen::MatrixXd U_;
  Eigen::LLT<Eigen::MatrixXd> capacitance_;
};

}  // namespace cellsim
