#pragma once
// Verlet neighbour lists with a skin, built from a cell list and reused until some particle has
// moved far enough (or h has grown enough) that a pair could have entered the cut-off unseen.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace cellsim {

// Compressed rows: the neighbours of i are index[offset[i] .. offset[i+1]), ascending.
struct PairList {
  std::vector<int> offset;
  std::vector<int> index;
  std::size_t pairs = 0;  // listed pairs, not counting padding
  long build = 0;         // a number no other build of any list in this process has, for caches
  int rows() const { return static_cast<int>(offset.size()) - 1; }
};

// The fluid-fluid rows are padded to a multiple of this with the index n (one past the last
// fluid particle), so that the pair loop can take them four pairs at a time.
constexpr int kPairLanes = 4;

class NeighbourLists {
 public:
  explicit NeighbourLists(double skin_m) : skin_(skin_m) {}

  // Rebuilds if needed for these cut-offs; returns true if it rebuilt. threads: as `cellsim run --threads`.
  bool update(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, double fluid_cutoff,
              double wall_fluid_cutoff, int threads = 1);

  void invalidate() { stale_ = true; }  // the next update rebuilds

  const PairList& fluid_fluid() const { return fluid_fluid_; }  // half list (j > i), rows padded
  const PairList& fluid_wall() const { return fluid_wall_; }    // every wall particle k near fluid i
  long builds() const { return builds_; }

 private:
  void build(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, int threads);

  double skin_;
  double list_fluid_cutoff_ = 0, list_wall_cutoff_ = 0;  // cut-off + skin at the last build
  double fluid_cutoff_ = 0, wall_fluid_cutoff_ = 0;
  Eigen::Matrix3Xd fluid_at_build_, wall_at_build_;
  PairList fluid_fluid_, fluid_wall_;
  std::vector<PairList> parts_;  // each thread's rows of both lists, while building with threads
  long builds_ = 0;
  bool stale_ = true;  // no valid list yet, or invalidated
};

}  // namespace cellsim
