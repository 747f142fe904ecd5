#pragma once
// Verlet neighbour lists with a skin, built from a cell list and reused until some particle has
// moved far enough (or h has grown enough) that a pair could have entered the cut-off unseen.
#include <cmath>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "core/periodic_box.hpp"

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
  // moved_at_most_m: how far any particle can have moved since the last update, if the caller knows
  // (a step's drift: dt max |v|), else INFINITY. While these bounds, added up since the last look at
  // the positions, leave the skin unused, no pass over the positions is needed; otherwise the update
  // measures the largest displacement itself. Either way it rebuilds exactly when it did without them.
  // box: a periodic tissue's period of the moment (the state's), which a build lists the wall pairs
  // in; when it changes, the caller counts the change in moved_at_most_m.
  bool update(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, double fluid_cutoff,
              double wall_fluid_cutoff, int threads = 1, double moved_at_most_m = INFINITY,
              const PeriodicBox& box = {});

  void invalidate() { stale_ = true; }  // the next update rebuilds
  // A tissue (model.md §10): fluid pairs only within a cell, fluid-wall pairs only with the cell's own
  // wall, and a third list of wall pairs of different cells within wall_wall_cutoff_m (of their nearest
  // images, in a periodic tissue: model.md §10b). Not called for one cell: then nothing is filtered and the
  // wall-wall list stays empty.
  void set_cells(std::vector<int> cell_of_fluid, std::vector<int> cell_of_wall, double wall_wall_cutoff_m);

  const PairList& fluid_fluid() const { return fluid_fluid_; }  // half list (j > i), rows padded
  const PairList& fluid_wall() const { return fluid_wall_; }    // every wall particle k near fluid i
  const PairList& wall_wall() const { return wall_wall_; }      // half list (l > k), of different cells
  long builds() const { return builds_; }
  long displacement_checks() const { return displacement_checks_; }  // passes over the positions

 private:
  void build(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, int threads, const PeriodicBox& box);

  double skin_;
  double list_fluid_cutoff_ = 0, list_wall_cutoff_ = 0;  // cut-off + skin at the last build
  double fluid_cutoff_ = 0, wall_fluid_cutoff_ = 0;
  Eigen::Matrix3Xd fluid_at_build_, wall_at_build_;
  PairList fluid_fluid_, fluid_wall_, wall_wall_;
  std::vector<int> cell_of_fluid_, cell_of_wall_;  // empty: one cell
  double wall_wall_cutoff_ = 0;
  std::vector<PairList> parts_;  // each thread's rows of both lists, while building with threads
  long builds_ = 0, displacement_checks_ = 0;
  double moved_bound_ = 0;  // no particle has moved farther since the build (valid unless stale_)
  bool stale_ = true;       // no valid list yet, or invalidated
};

}  // namespace cellsim
