#include "physics/wall_fluid.hpp"

#include <algorithm>

namespace cellsim {
namespace {

// Fluid rows [begin, end), a chunk of rows at a time: pass 1 gathers r^2 of every listed pair; pass
// 2 evaluates f(r) over that flat array (a loop the compiler vectorises: it holds the divisions);
// pass 3 applies f x_ik to both particles. A chunk's pairs stay in cache between the passes (a
// tissue's pairs are many times the cache); each pair adds in the same order as in one pass. The
// wall sums are zeroed as the chunks first reach them, not in one sweep before: a tissue's walls are
// larger than the cache, and a sweep would have evicted a column by the time its pairs add to it.
// A function of its own, so that its scalars are not re-read after every store.
void add_rows(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const PairList& pairs,
              const LennardJones& lj, Eigen::Index begin, Eigen::Index end, double* f, Eigen::Matrix3Xd& fluid_force,
              Eigen::Matrix3Xd& on_wall) {
  constexpr Eigen::Index kChunkRows = 256;
  const int* offset = pairs.offset.data();
  const int* index = pairs.index.data();
  Eigen::Index zeroed = 0;  // columns [0, zeroed) are zeroed; the rows so far reached only those
  for (Eigen::Index c0 = begin; c0 < end; c0 += kChunkRows) {
    const Eigen::Index c1 = std::min(c0 + kChunkRows, end);
    Eigen::Index reach = 0;  // one past the last wall particle the chunk reaches
    for (Eigen::Index i = c0; i < c1; ++i) {
      const Eigen::Vector3d xi = fluid_x.col(i);
      for (int q = offset[i]; q < offset[i + 1]; ++q) {
        reach = std::max<Eigen::Index>(reach, index[q] + 1);
        f[q] = (xi - wall_x.col(index[q])).squaredNorm();
      }
    }
    if (reach > zeroed) {
      on_wall.middleCols(zeroed, reach - zeroed).setZero();
      zeroed = reach;
    }
    for (int q = offset[c0]; q < offset[c1]; ++q) f[q] = lj.f_of_r2(f[q]);
    for (Eigen::Index i = c0; i < c1; ++i) {
      const Eigen::Vector3d xi = fluid_x.col(i);
      Eigen::Vector3d force_i = Eigen::Vector3d::Zero();
      for (int q = offset[i]; q < offset[i + 1]; ++q) {
        const int k = index[q];
        const Eigen::Vector3d fik = f[q] * (xi - wall_x.col(k));
        force_i += fik;
        on_wall.col(k) -= fik;
      }
      fluid_force.col(i) += force_i;
    }
  }
  on_wall.rightCols(on_wall.cols() - zeroed).setZero();
}

}  // namespace

// The wall's share goes through per-thread sums (block_sums.hpp); each fluid row is one thread's.
void wall_fluid_forces(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const PairList& pairs,
                       const LennardJones& lj, int threads, Eigen::Matrix3Xd& fluid_force, Eigen::Matrix3Xd& on_wall,
                       WallFluidScratch& scratch) {
  // One thread adds straight into on_wall (add_rows zeroes it); several add into copies of their own,
  // which block_sums.hpp adds into a zeroed on_wall.
  if (threads > 1)
    on_wall.setZero(3, wall_x.cols());
  else
    on_wall.resize(3, wall_x.cols());
  scratch.pair_f.resize(static_cast<Eigen::Index>(pairs.index.size()));
  double* f = scratch.pair_f.data();
  scratch.sums.add(threads, pairs.rows(), on_wall, [&](int, Eigen::Index begin, Eigen::Index end, Eigen::Matrix3Xd& out) {
    add_rows(fluid_x, wall_x, pairs, lj, begin, end, f, fluid_force, out);
  });
}

}  // namespace cellsim
