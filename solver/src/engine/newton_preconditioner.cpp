#include "engine/newton_preconditioner.hpp"

#include <stdexcept>

#include "parallel/threads.hpp"

namespace cellsim {
namespace {

// The first shift tried, as a share of the mean |diagonal|, and its growth per failed factorization.
constexpr double kFirstShiftShare = 1e-3, kShiftGrowth = 4;
constexpr int kMaxShifts = 30;

}  // namespace

void NewtonPreconditioner::factor(const Eigen::SparseMatrix<double>& stiffness, const Eigen::VectorXd& volume_gradient,
                                  const CellRanges& cells, const std::vector<double>& volume_stiffness_Pa_m3,
                                  bool cells_joined) {
  const SerialOpenMP serial;
  if (!analyzed_) {
    llt_.cholmod().print = 0;  // a matrix that is not positive definite is expected (a fold): shifted, not reported
    llt_.analyzePattern(stiffness);
    analyzed_ = true;
  }
  const double first_shift_N_m = kFirstShiftShare * stiffness.diagonal().cwiseAbs().mean();
  shift_N_m_ = 0;
  for (int attempt = 0;; ++attempt) {
    llt_.setShift(shift_N_m_);
    llt_.factorize(stiffness);
    if (llt_.info() == Eigen::Success) break;
    if (attempt == kMaxShifts) throw std::logic_error("the Newton preconditioner did not factor with any shift");
    shift_N_m_ = shift_N_m_ == 0 ? first_shift_N_m : kShiftGrowth * shift_N_m_;
  }
  cells_ = &cells;
  g_ = volume_gradient;
  sprung_.clear();
  if (cells_joined) {
    for (int c = 0; c < cells.count(); ++c)
      if (volume_stiffness_Pa_m3[static_cast<std::size_t>(c)] > 0) sprung_.push_back(c);
    const auto C = static_cast<Eigen::Index>(sprung_.size());
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(g_.size(), C);
    for (Eigen::Index j = 0; j < C; ++j) {
      const int c = sprung_[static_cast<std::size_t>(j)];
      const Eigen::Index first = 3 * cells.wall[c], size = 3 * cells.wall_count(c);
      G.col(j).segment(first, size) = g_.segment(first, size);
    }
    U_ = llt_.solve(G);
    Eigen::MatrixXd capacitance = G.transpose() * U_;
    for (Eigen::Index j = 0; j < C; ++j)
      capacitance(j, j) += 1.0 / volume_stiffness_Pa_m3[static_cast<std::size_t>(sprung_[static_cast<std::size_t>(j)])];
    capacitance_.compute(capacitance);
    scale_.assign(volume_stiffness_Pa_m3.size(), 0.0);  // the per-cell update is not used
    return;
  }
  u_ = llt_.solve(g_);
  scale_.assign(volume_stiffness_Pa_m3.size(), 0.0);
  for (int c = 0; c < cells.count(); ++c) {
    const double k = volume_stiffness_Pa_m3[static_cast<std::size_t>(c)];
    const Eigen::Index first = 3 * cells.wall[c], size = 3 * cells.wall_count(c);
    if (k > 0) scale_[static_cast<std::size_t>(c)] = 1.0 / (1.0 / k + g_.segment(first, size).dot(u_.segment(first, size)));
  }
}

// (A + k g g^T)^-1 r = A^-1 r - u (g . A^-1 r) / (1/k + g . u), u = A^-1 g, per cell (its rows alone);
// cells joined: (A + G K G^T)^-1 r = A^-1 r - U (K^-1 + G^T U)^-1 G^T A^-1 r, U = A^-1 G.
Eigen::VectorXd NewtonPreconditioner::solve(const Eigen::VectorXd& r) const {
  const SerialOpenMP serial;
  Eigen::VectorXd z = llt_.solve(r);
  if (!sprung_.empty()) {
    Eigen::VectorXd Gz(static_cast<Eigen::Index>(sprung_.size()));
    for (std::size_t j = 0; j < sprung_.size(); ++j) {
      const Eigen::Index first = 3 * cells_->wall[sprung_[j]], size = 3 * cells_->wall_count(sprung_[j]);
      Gz[static_cast<Eigen::Index>(j)] = g_.segment(first, size).dot(z.segment(first, size));
    }
    z -= U_ * capacitance_.solve(Gz);
    return z;
  }
  for (int c = 0; c < cells_->count(); ++c) {
    const double scale = scale_[static_cast<std::size_t>(c)];
    if (scale == 0) continue;
    const Eigen::Index first = 3 * cells_->wall[c], size = 3 * cells_->wall_count(c);
    z.segment(first, size) -= (scale * g_.segment(first, size).dot(z.segment(first, size))) * u_.segment(first, size);
  }
  return z;
}

}  // namespace cellsim
