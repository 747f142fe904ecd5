#include "geometry/neighbours.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include "parallel/threads.hpp"

namespace cellsim {
namespace {

double moved2(const Eigen::Matrix3Xd& now, const Eigen::Matrix3Xd& then, Eigen::Index begin, Eigen::Index end) {
  return (now.middleCols(begin, end - begin) - then.middleCols(begin, end - begin)).colwise().squaredNorm().maxCoeff();
}

// Uniform grid over a bounding box; particles binned by counting sort (deterministic order). Along a
// periodic axis of `box` the grid covers one period and wraps around.
constexpr double kMaxCellsPerSide = 200;

struct CellGrid {
  Eigen::Vector3d origin;
  Eigen::Vector3d size;
  std::array<int, 3> dims;
  std::array<double, 3> period{0, 0, 0};  // > 0: the axis wraps
  std::vector<int> start;  // per cell, into order
  std::vector<int> order;  // particle indices grouped by cell

  CellGrid(const Eigen::Matrix3Xd& x, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double cell_size,
           const PeriodicBox& box = {})
      : origin(lo), size(Eigen::Vector3d::Constant(std::max(cell_size, (hi - lo).maxCoeff() / kMaxCellsPerSide))) {
    // Larger cells still cover the cut-off; the cap keeps a stray particle from allocating a huge grid.
    for (int d = 0; d < 3; ++d) dims[d] = std::max(1, static_cast<int>(std::floor((hi[d] - lo[d]) / size[d])) + 1);
    period[0] = box.length_x_m;
    period[1] = box.length_y_m;
    for (int d = 0; d < 2; ++d)
      if (period[d] > 0) {  // whole cells of at least the cut-off to a period
        origin[d] = 0;
        dims[d] = std::clamp(static_cast<int>(std::floor(period[d] / cell_size)), 1, static_cast<int>(kMaxCellsPerSide));
        size[d] = period[d] / dims[d];
      }
    std::vector<int> cell_of(static_cast<std::size_t>(x.cols()));
    start.assign(static_cast<std::size_t>(dims[0] * dims[1] * dims[2]) + 1, 0);
    for (Eigen::Index i = 0; i < x.cols(); ++i) {
      const int c = cell_index(x.col(i));
      cell_of[static_cast<std::size_t>(i)] = c;
      ++start[static_cast<std::size_t>(c) + 1];
    }
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    order.resize(static_cast<std::size_t>(x.cols()));
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (Eigen::Index i = 0; i < x.cols(); ++i)
      order[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_of[static_cast<std::size_t>(i)])]++)] =
          static_cast<int>(i);
  }

  std::array<int, 3> coords(const Eigen::Vector3d& p) const {
    std::array<int, 3> c{};
    for (int d = 0; d < 3; ++d) {
      const double u = period[d] > 0 ? p[d] - period[d] * std::floor(p[d] / period[d]) : p[d] - origin[d];
      c[d] = std::clamp(static_cast<int>(std::floor(u / size[d])), 0, dims[d] - 1);
    }
    return c;
  }

  // The grid rows along axis d next to row c, each once (a period of fewer than three rows: all of them).
  int near_rows(int c, int d, std::array<int, 3>& rows) const {
    if (period[d] > 0) {
      if (dims[d] < 3) {
        for (int r = 0; r < dims[d]; ++r) rows[static_cast<std::size_t>(r)] = r;
        return dims[d];
      }
      rows = {(c + dims[d] - 1) % dims[d], c, (c + 1) % dims[d]};
      return 3;
    }
    int n = 0;
    for (int r = std::max(c - 1, 0); r <= std::min(c + 1, dims[d] - 1); ++r) rows[static_cast<std::size_t>(n++)] = r;
    return n;
  }
  int cell_index(const Eigen::Vector3d& p) const {
    const auto c = coords(p);
    return (c[2] * dims[1] + c[1]) * dims[0] + c[0];
  }

  // Calls visit(j) for every particle of this grid in the 27 cells around p.
  template <class Visit>
  void for_each_near(const Eigen::Vector3d& p, Visit&& visit) const {
    const auto c = coords(p);
    std::array<int, 3> xs{}, ys{}, zs{};
    const int nx = near_rows(c[0], 0, xs), ny = near_rows(c[1], 1, ys), nz = near_rows(c[2], 2, zs);
    for (int iz = 0; iz < nz; ++iz)
      for (int iy = 0; iy < ny; ++iy)
        for (int ix = 0; ix < nx; ++ix) {
          const int cell = (zs[static_cast<std::size_t>(iz)] * dims[1] + ys[static_cast<std::size_t>(iy)]) * dims[0] +
                           xs[static_cast<std::size_t>(ix)];
          for (int k = start[static_cast<std::size_t>(cell)]; k < start[static_cast<std::size_t>(cell) + 1]; ++k)
            visit(order[static_cast<std::size_t>(k)]);
        }
  }
};

// The largest distance any particle has moved since the build (one square root), in fixed blocks.
double max_displacement(const Eigen::Matrix3Xd& now, const Eigen::Matrix3Xd& then, int threads) {
  if (now.cols() != then.cols()) return INFINITY;
  if (now.cols() == 0) return 0.0;
  const double max2 = reduce_blocks<double>(
      threads, now.cols(),
      [&](Eigen::Index begin, Eigen::Index end) { return moved2(now, then, begin, end); },
      [](double a, double b) { return std::max(a, b); });
  return std::sqrt(max2);
}

// Which cell each particle is in, for a tissue's lists (null pointers: one cell, nothing filtered).
struct CellOf {
  const int* fluid = nullptr;
  const int* wall = nullptr;
  bool same_fluid(int i, int j) const { return !fluid || fluid[i] == fluid[j]; }
  bool own_wall(int i, int k) const { return !fluid || fluid[i] == wall[k]; }
};

// Rows [first, last) of both lists, each into `fluid_fluid` and `fluid_wall` (offsets from 0).
void list_rows(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const CellGrid& fluid_grid,
               const CellGrid& wall_grid, double ff2, double fw2, CellOf cell_of, int first, int last,
               PairList& fluid_fluid, PairList& fluid_wall) {
  const int n = static_cast<int>(fluid_x.cols());
  fluid_fluid.offset.assign(1, 0);
  fluid_fluid.index.clear();
  fluid_fluid.pairs = 0;
  fluid_wall.offset.assign(1, 0);
  fluid_wall.index.clear();
  fluid_wall.pairs = 0;
  std::vector<int> row;
  for (int i = first; i < last; ++i) {
    const Eigen::Vector3d xi = fluid_x.col(i);
    row.clear();
    fluid_grid.for_each_near(xi, [&](int j) {
      if (j > i && (fluid_x.col(j) - xi).squaredNorm() < ff2 && cell_of.same_fluid(i, j)) row.push_back(j);
    });
    std::sort(row.begin(), row.end());  // ascending j: memory order, and independent of binning
    fluid_fluid.pairs += row.size();
    while (row.size() % kPairLanes) row.push_back(n);
    fluid_fluid.index.insert(fluid_fluid.index.end(), row.begin(), row.end());
    fluid_fluid.offset.push_back(static_cast<int>(fluid_fluid.index.size()));

    row.clear();
    wall_grid.for_each_near(xi, [&](int k) {
      if ((wall_x.col(k) - xi).squaredNorm() < fw2 && cell_of.own_wall(i, k)) row.push_back(k);
    });
    std::sort(row.begin(), row.end());
    fluid_wall.pairs += row.size();
    fluid_wall.index.insert(fluid_wall.index.end(), row.begin(), row.end());
    fluid_wall.offset.push_back(static_cast<int>(fluid_wall.index.size()));
  }
}

// Wall particles l > k of other cells within sqrt(ww2) of k (their nearest images), for every k (one
// thread: built only for tissues, and only when the lists are).
void list_wall_wall(const Eigen::Matrix3Xd& wall_x, const CellGrid& grid, double ww2, const int* cell_of_wall,
                    const PeriodicBox& box, PairList& list) {
  list.offset.assign(1, 0);
  list.index.clear();
  std::vector<int> row;
  for (int k = 0; k < static_cast<int>(wall_x.cols()); ++k) {
    const Eigen::Vector3d xk = wall_x.col(k);
    row.clear();
    grid.for_each_near(xk, [&](int l) {
      if (l > k && cell_of_wall[l] != cell_of_wall[k] && box.nearest_image(wall_x.col(l) - xk).squaredNorm() < ww2)
        row.push_back(l);
    });
    std::sort(row.begin(), row.end());
    list.index.insert(list.index.end(), row.begin(), row.end());
    list.offset.push_back(static_cast<int>(list.index.size()));
  }
  list.pairs = list.index.size();
}

// The threads' parts of one list (parts[2 b + which]) joined in order, each thread copying its own.
void join_parts(const std::vector<PairList>& parts, int threads, int which, PairList& list) {
  const auto part_of = [&](int b) -> const PairList& { return parts[static_cast<std::size_t>(2 * b + which)]; };
  std::vector<int> first_index(static_cast<std::size_t>(threads) + 1, 0), first_row(first_index);
  list.pairs = 0;
  for (int b = 0; b < threads; ++b) {
    const auto next = static_cast<std::size_t>(b) + 1;
    first_index[next] = first_index[next - 1] + static_cast<int>(part_of(b).index.size());
    first_row[next] = first_row[next - 1] + part_of(b).rows();
    list.pairs += part_of(b).pairs;
  }
  list.index.resize(static_cast<std::size_t>(first_index.back()));
  list.offset.resize(static_cast<std::size_t>(first_row.back()) + 1);
  list.offset[0] = 0;
  run_on_threads(threads, [&](int t, int count) {
    for (int b = t; b < threads; b += count) {
      const PairList& part = part_of(b);
      const int base = first_index[static_cast<std::size_t>(b)], row = first_row[static_cast<std::size_t>(b)];
      std::copy(part.index.begin(), part.index.end(), list.index.begin() + base);
      for (int r = 1; r <= part.rows(); ++r)
        list.offset[static_cast<std::size_t>(row + r)] = base + part.offset[static_cast<std::size_t>(r)];
    }
  });
}

}  // namespace

void NeighbourLists::set_cells(std::vector<int> cell_of_fluid, std::vector<int> cell_of_wall, double wall_wall_cutoff_m) {
  cell_of_fluid_ = std::move(cell_of_fluid);
  cell_of_wall_ = std::move(cell_of_wall);
  wall_wall_cutoff_ = wall_wall_cutoff_m;
  stale_ = true;
}

bool NeighbourLists::update(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, double fluid_cutoff,
                            double wall_fluid_cutoff, int threads, double moved_at_most_m, const PeriodicBox& box) {
  fluid_cutoff_ = fluid_cutoff;
  wall_fluid_cutoff_ = wall_fluid_cutoff;
  if (!stale_) {
    // A pair now within the cut-off was within cut-off + 2 max_disp at the build.
    const auto lists_hold = [&](double max_disp) {
      const double moved = 2.0 * max_disp;
      return fluid_cutoff + moved <= list_fluid_cutoff_ && wall_fluid_cutoff + moved <= list_wall_cutoff_ &&
             (cell_of_wall_.empty() || wall_wall_cutoff_ + moved <= wall_wall_cutoff_ + skin_);
    };
    // The bound holds in exact arithmetic; the margin covers the round-off of the positions (about
    // 1e-20 m a step) and of the measured displacement, so the bound keeps the lists only where the
    // measurement would keep them too.
    moved_bound_ += moved_at_most_m;
    if (lists_hold(moved_bound_ + 1e-6 * skin_)) return false;
    ++displacement_checks_;
    moved_bound_ = std::max(max_displacement(fluid_x, fluid_at_build_, threads),
                            max_displacement(wall_x, wall_at_build_, threads));
    if (lists_hold(moved_bound_)) return false;
  }
  build(fluid_x, wall_x, threads, box);
  return true;
}

void NeighbourLists::build(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, int threads,
                           const PeriodicBox& box) {
  list_fluid_cutoff_ = fluid_cutoff_ + skin_;
  list_wall_cutoff_ = wall_fluid_cutoff_ + skin_;
  fluid_at_build_ = fluid_x;
  wall_at_build_ = wall_x;
  ++builds_;
  stale_ = false;
  moved_bound_ = 0;

  // The box of every particle (a closed-cell fluid has none of its own: fluid_x is empty).
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = Eigen::Vector3d::Constant(-INFINITY);
  for (const Eigen::Matrix3Xd* x : {&fluid_x, &wall_x})
    if (x->cols()) {
      lo = lo.cwiseMin(x->rowwise().minCoeff());
      hi = hi.cwiseMax(x->rowwise().maxCoeff());
    }
  static std::atomic<long> builds_in_process{0};
  fluid_fluid_.build = fluid_wall_.build = wall_wall_.build = ++builds_in_process;
  if (!cell_of_wall_.empty()) {
    const double ww = wall_wall_cutoff_ + skin_;
    list_wall_wall(wall_x, CellGrid(wall_x, lo, hi, ww, box), ww * ww, cell_of_wall_.data(), box, wall_wall_);
  }
  const int n = static_cast<int>(fluid_x.cols());
  if (n == 0) {  // no fluid particles: no fluid rows
    for (PairList* list : {&fluid_fluid_, &fluid_wall_}) list->offset.assign(1, 0), list->index.clear(), list->pairs = 0;
    return;
  }
  const double ff2 = list_fluid_cutoff_ * list_fluid_cutoff_, fw2 = list_wall_cutoff_ * list_wall_cutoff_;
  const CellGrid fluid_grid(fluid_x, lo, hi, list_fluid_cutoff_);
  const CellGrid wall_grid(wall_x, lo, hi, list_wall_cutoff_);
  const CellOf cell_of = cell_of_fluid_.empty() ? CellOf{} : CellOf{cell_of_fluid_.data(), cell_of_wall_.data()};
  const auto rows = [&](int first, int last, PairList& fluid_fluid, PairList& fluid_wall) {
    list_rows(fluid_x, wall_x, fluid_grid, wall_grid, ff2, fw2, cell_of, first, last, fluid_fluid, fluid_wall);
  };
  if (threads <= 1 || n < 2 * threads) {
    rows(0, n, fluid_fluid_, fluid_wall_);
    return;
  }
  // Each thread lists its own particles' rows (the particles every loop of the step gives it), then
  // copies them into place: the lists come out the same as from one thread.
  parts_.resize(static_cast<std::size_t>(2 * threads));
  run_on_threads(threads, [&](int t, int count) {
    for (int b = t; b < threads; b += count)
      rows(static_cast<int>(block_start(n, b, threads)), static_cast<int>(block_start(n, b + 1, threads)),
           parts_[static_cast<std::size_t>(2 * b)], parts_[static_cast<std::size_t>(2 * b + 1)]);
  });
  join_parts(parts_, threads, 0, fluid_fluid_);
  join_parts(parts_, threads, 1, fluid_wall_);
}

}  // namespace cellsim
