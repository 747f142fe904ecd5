#include "physics/pressure_coupling.hpp"

#include <cmath>

#include "parallel/simd4.hpp"
#include "parallel/threads.hpp"

namespace cellsim {
namespace {

using simd::double4;

// Pair q's weight w W and backstop p_b W, for one pair (T = double: the three coordinates of the
// separation fluid -> wall and the element's unit normal) or four (T = double4, a pair a lane). Pairs
// the list holds beyond the kernel's support (its skin) weigh nothing: W is 0 there.
template <class T>
void weigh(const T (&to_wall)[3], const T (&normal)[3], const CubicSplineKernel& kernel, const PressureCouplingLaw& law,
           double fade, T& weight, T& backstop) {
  const T r2 = to_wall[0] * to_wall[0] + to_wall[1] * to_wall[1] + to_wall[2] * to_wall[2];
  const T W = kernel.W(simd::sqrt(r2));
  const T depth = to_wall[0] * normal[0] + to_wall[1] * normal[1] + to_wall[2] * normal[2];
  weight = one_sided_weight(depth, fade) * W;
  backstop = backstop_pressure_Pa(depth, law) * W;
}

// Weights of the pairs of fluid rows [begin, end), four pairs of a row at a time and the rest one by
// one (a pair's numbers do not depend on which); returns true if any has a backstop.
bool weigh_rows(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x, const Eigen::Matrix3Xd& unit_normal,
                const PairList& pairs, const CubicSplineKernel& kernel, const PressureCouplingLaw& law, double fade,
                Eigen::Index begin, Eigen::Index end, double* weight, double* backstop) {
  const int* offset = pairs.offset.data();
  const int* index = pairs.index.data();
  const double* wall = wall_x.data();
  const double* normal = unit_normal.data();
  double4 any = {};
  double any_one = 0;
  for (Eigen::Index i = begin; i < end; ++i) {
    const double* xi = fluid_x.col(i).data();
    int q = offset[i];
    for (; q + 4 <= offset[i + 1]; q += 4) {
      const int* k = index + q;
      double4 to_wall[3], n[3];
      for (int d = 0; d < 3; ++d) {
        to_wall[d] = double4{wall[3 * k[0] + d], wall[3 * k[1] + d], wall[3 * k[2] + d], wall[3 * k[3] + d]} - xi[d];
        n[d] = double4{normal[3 * k[0] + d], normal[3 * k[1] + d], normal[3 * k[2] + d], normal[3 * k[3] + d]};
      }
      double4 w, b;
      weigh(to_wall, n, kernel, law, fade, w, b);
      simd::store(weight + q, w);
      simd::store(backstop + q, b);
      any = any + simd::abs(b);
    }
    for (; q < offset[i + 1]; ++q) {
      const int k = index[q];
      const double to_wall[3] = {wall[3 * k] - xi[0], wall[3 * k + 1] - xi[1], wall[3 * k + 2] - xi[2]};
      const double n[3] = {normal[3 * k], normal[3 * k + 1], normal[3 * k + 2]};
      weigh(to_wall, n, kernel, law, fade, weight[q], backstop[q]);
      any_one = any_one + simd::abs(backstop[q]);
    }
  }
  return simd::sum(any) != 0 || any_one != 0;
}

// The wall term of Eq 10 for fluid rows [begin, end).
void add_density_rows(const FluidParticles& fluid, const WallParticles& wall, const PairList& pairs,
                      const PressureCouplingScratch& s, Eigen::Index begin, Eigen::Index end, Eigen::VectorXd& drho_dt) {
  const int* offset = pairs.offset.data();
  const int* index = pairs.index.data();
  for (Eigen::Index i = begin; i < end; ++i) {
    double divergence = 0;
    for (int q = offset[i]; q < offset[i + 1]; ++q) {
      const int k = index[q];
      divergence += s.weight[q] * (fluid.v.col(i) - wall.v.col(k)).dot(s.area_vector.col(k));
    }
    drho_dt[i] += 2.0 * fluid.rho[i] * divergence;
  }
}

// The pair forces of fluid rows [begin, end): on the fluid into fluid_force, their reactions into
// on_wall. With `backstop`, only the backstop's part, and its power (returned).
template <bool kBackstop>
double add_force_rows(const FluidParticles& fluid, const Eigen::VectorXd& pressure, const WallParticles& wall,
                      const PairList& pairs, const PressureCouplingScratch& s, Eigen::Index begin, Eigen::Index end,
                      Eigen::Matrix3Xd& fluid_force, Eigen::Matrix3Xd& on_wall) {
  const int* offset = pairs.offset.data();
  const int* index = pairs.index.data();
  double power = 0;
  for (Eigen::Index i = begin; i < end; ++i) {
    const double two_volume = 2.0 * fluid.m[i] / fluid.rho[i];
    Eigen::Vector3d force_i = Eigen::Vector3d::Zero();
    for (int q = offset[i]; q < offset[i + 1]; ++q) {
      const int k = index[q];
      const double coefficient = kBackstop ? s.backstop[q] : pressure[i] * s.weight[q];
      if (kBackstop && coefficient == 0) continue;  // few pairs have one: skipped; the pressure's zeros add nothing
      const Eigen::Vector3d fik = -two_volume * coefficient * s.area_vector.col(k);
      force_i += fik;
      on_wall.col(k) -= fik;
      if (kBackstop) power += fik.dot(fluid.v.col(i) - wall.v.col(k));
    }
    fluid_force.col(i) += force_i;
  }
  return power;
}

}  // namespace

void pressure_coupling_weights(const Eigen::Matrix3Xd& fluid_x, const Eigen::Matrix3Xd& wall_x,
                               const Eigen::Matrix3Xd& vertex_normal, const PairList& pairs,
                               const CubicSplineKernel& kernel, const PressureCouplingLaw& law, int threads,
                               PressureCouplingScratch& scratch) {
  const auto n_pairs = static_cast<Eigen::Index>(pairs.index.size());
  scratch.weight.resize(n_pairs);
  scratch.backstop.resize(n_pairs);
  scratch.area_vector.resize(3, wall_x.cols());
  scratch.unit_normal.resize(3, wall_x.cols());
  for_blocks(threads, wall_x.cols(), [&](Eigen::Index begin, Eigen::Index end) {
    const auto N = vertex_normal.middleCols(begin, end - begin);
    scratch.area_vector.middleCols(begin, end - begin) = N / 6.0;
    scratch.unit_normal.middleCols(begin, end - begin) = N.colwise().normalized();
  });
  const double fade = kFadeOverH * kernel.h();
  scratch.any_backstop = reduce_blocks<bool>(
      threads, pairs.rows(),
      [&](Eigen::Index begin, Eigen::Index end) {
        return weigh_rows(fluid_x, wall_x, scratch.unit_normal, pairs, kernel, law, fade, begin, end, scratch.weight.data(),
                          scratch.backstop.data());
      },
      [](bool a, bool b) { return a || b; });
}

void add_pressure_coupling_density_rates(const FluidParticles& fluid, const WallParticles& wall, const PairList& pairs,
                                         const PressureCouplingScratch& scratch, int threads, Eigen::VectorXd& drho_dt) {
  for_blocks(threads, pairs.rows(), [&](Eigen::Index begin, Eigen::Index end) {
    add_density_rows(fluid, wall, pairs, scratch, begin, end, drho_dt);
  });
}

// What the rows add to wall particles goes through per-block sums (block_sums.hpp); the backstop's
// part, when some pair has one, in a second pass of its own.
double pressure_coupling_forces(const FluidParticles& fluid, const Eigen::VectorXd& pressure, const WallParticles& wall,
                                const PairList& pairs, int threads, PressureCouplingScratch& scratch,
                                Eigen::Matrix3Xd& fluid_force, Eigen::Matrix3Xd& on_wall,
                                Eigen::Matrix3Xd& backstop_on_wall) {
  on_wall.setZero(3, wall.size());
  scratch.force_sums.add(threads, pairs.rows(), on_wall,
                         [&](int, Eigen::Index begin, Eigen::Index end, Eigen::Matrix3Xd& out) {
                           add_force_rows<false>(fluid, pressure, wall, pairs, scratch, begin, end, fluid_force, out);
                         });
  backstop_on_wall.setZero(3, wall.size());
  if (!scratch.any_backstop) return 0.0;
  scratch.block_backstop_W.assign(static_cast<std::size_t>(std::max(threads, 1)), 0.0);
  scratch.backstop_sums.add(threads, pairs.rows(), backstop_on_wall,
                            [&](int block, Eigen::Index begin, Eigen::Index end, Eigen::Matrix3Xd& out) {
                              scratch.block_backstop_W[static_cast<std::size_t>(block)] = add_force_rows<true>(
                                  fluid, pressure, wall, pairs, scratch, begin, end, fluid_force, out);
                            });
  on_wall += backstop_on_wall;
  double power = 0;
  for (double part : scratch.block_backstop_W) power += part;
  return power;
}

}  // namespace cellsim
