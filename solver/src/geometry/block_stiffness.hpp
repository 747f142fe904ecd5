#pragma once
// A stiffness matrix of 3 x 3 blocks, one per particle on the diagonal and one per joined pair (both
// ways), its pattern fixed when it is made: the quasi-static preconditioner (engine/newton_preconditioner.hpp)
// assembles it at every factorization of a relaxation, its laws adding their blocks into slots laid out
// once instead of sorting a list of entries each time.
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace cellsim {

class BlockStiffness {
 public:
  // particles: the blocks' count along each side; pairs: the joined particles (a != b, each pair once or
  // twice, either order), for the wall its bonds (WallMesh::bonds, every triangle's edges).
  BlockStiffness(Eigen::Index particles, const std::vector<std::array<int, 2>>& pairs);

  void set_zero();
  // Adds `block` at rows of particle a and columns of particle b; throws std::logic_error where the pattern
  // has no such block (a law reaching beyond the pairs it was given).
  void add(int a, int b, const Eigen::Matrix3d& block);
  // A pair law's block between a and b: `block` at (a, a) and (b, b), minus it at (a, b) and (b, a).
  void add_pair(int a, int b, const Eigen::Matrix3d& block);
  // Whether the pattern has a block at particles a and b (a law whose pairs change within a relaxation,
  // a tissue's contacts, adds only those it has).
  bool joins(int a, int b) const;
  // The matrix (3 particles x 3 particles), every pattern entry stored, zero or not.
  const Eigen::SparseMatrix<double>& matrix() const { return matrix_; }

 private:
  Eigen::Index slot(int a, int b) const;  // where block (a, b)'s entry (0, 0) sits in the values

  Eigen::SparseMatrix<double> matrix_;
  std::vector<std::vector<int>> rows_of_column_;  // per particle b, the particles a of its column, sorted
};

}  // namespace cellsim
