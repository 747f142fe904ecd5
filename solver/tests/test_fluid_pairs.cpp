// The four-lane fluid pair loop against a plain one-pair-at-a-time sum over every pair within the
// kernel support (Eqs 3, 4, 10 written out in the test): the lanes, the transposes and the padding of
// the pair list must change nothing beyond round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <utility>

#include "parallel/threads.hpp"
#include "physics/fluid_pairs.hpp"

using namespace cellsim;

namespace {

// A jittered lattice with random velocities, masses and densities (so every factor matters).
FluidParticles random_fluid(int n_side, double dx, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2 * dx, 0.2 * dx), speed(-0.5, 0.5), spread(0.9, 1.1);
  FluidParticles f;
  const int n = n_side * n_side * n_side;
  f.x.resize(3, n);
  f.v.resize(3, n);
  f.m.resize(n);
  f.rho.resize(n);
  for (int p = 0; p < n; ++p) {
    f.x.col(p) << (p % n_side) * dx + jitter(rng), (p / n_side % n_side) * dx + jitter(rng),
        (p / (n_side * n_side)) * dx + jitter(rng);
    f.v.col(p) << speed(rng), speed(rng), speed(rng);
    f.m[p] = 1000.0 * dx * dx * dx * spread(rng);
    f.rho[p] = 1000.0 * spread(rng);
  }
  return f;
}

// A random fluid of n_side^3 particles on spacing dx with its pair list (a skin of 0.2 dx) for a kernel of
// h = 1.3 dx, and the tests' EOS (P_T 200 kPa, K 20 MPa).
struct ListedFluid {
  ListedFluid(int n_side, double dx, unsigned seed)
      : f(random_fluid(n_side, dx, seed)), kernel(1.3 * dx), lists(0.2 * dx) {
    lists.update(f.x, Eigen::Matrix3Xd(3, 0), kernel.support(), 0.0);
  }
  const PairList& pairs() const { return lists.fluid_fluid(); }
  FluidParticles f;
  CubicSplineKernel kernel;
  NeighbourLists lists;
  EquationOfState eos{2e5, 20e6, 1000, 7};
};

}  // namespace

// Eqs 3 and 4 (Morris' form) and 10 written out here rather than taken from sph_terms.hpp, one pair
// at a time over every pair within the kernel support.
struct PlainSums {
  Eigen::Matrix3Xd force;
  Eigen::VectorXd drho;
  double viscous_loss_W = 0;  // -F_visc,ij . v_ij summed over pairs: what Eq 4 takes out of the kinetic energy
  int pairs_in_support = 0;
};

PlainSums plain_pair_sums(const FluidParticles& f, const CubicSplineKernel& kernel, const EquationOfState& eos,
                          double viscosity, double diffusion = 0) {
  const Eigen::Index n = f.size();
  PlainSums s{Eigen::Matrix3Xd::Zero(3, n), Eigen::VectorXd::Zero(n)};
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i + 1; j < n; ++j) {
      const Eigen::Vector3d xij = f.x.col(i) - f.x.col(j), vij = f.v.col(i) - f.v.col(j);
      if (xij.norm() >= kernel.support()) continue;
      ++s.pairs_in_support;
      const double g = kernel.dW_dr_over_r(xij.norm());
      const double Ai = eos.pressure(f.rho[i]) / (f.rho[i] * f.rho[i]), Aj = eos.pressure(f.rho[j]) / (f.rho[j] * f.rho[j]);
      const Eigen::Vector3d viscous = f.m[i] * f.m[j] * 2 * viscosity / (f.rho[i] * f.rho[j]) * g * vij;
      const Eigen::Vector3d fij = -f.m[i] * f.m[j] * (Ai + Aj) * g * xij + viscous;
      s.viscous_loss_W -= viscous.dot(vij);
      s.force.col(i) += fij;
      s.force.col(j) -= fij;
      s.drho[i] += f.m[j] * g * vij.dot(xij);
      s.drho[j] += f.m[i] * g * vij.dot(xij);
      // delta-SPH: psi_ij . grad_i W = 2 (rho_i - rho_j) x_ij . (g x_ij) / r^2, times V_j (and the mirror for j)
      const double psi_dot_grad = 2 * (f.rho[i] - f.rho[j]) * g * xij.squaredNorm() / xij.squaredNorm();
      s.drho[i] += diffusion * f.m[j] / f.rho[j] * psi_dot_grad;
      s.drho[j] -= diffusion * f.m[i] / f.rho[i] * psi_dot_grad;
    }
  return s;
}

// The loop's rates equal the plain sums to round-off, and its pressures are the EOS's.
void expect_plain_sums(const FluidParticles& f, const EquationOfState& eos, const FluidRates& rates,
                       const PlainSums& plain) {
  ASSERT_FALSE(rates.force.hasNaN() || rates.drho_dt.hasNaN());  // maxCoeff below would pass over a NaN
  const double force_scale = plain.force.colwise().norm().maxCoeff(), drho_scale = plain.drho.cwiseAbs().maxCoeff();
  ASSERT_GT(force_scale, 0.0);
  ASSERT_GT(drho_scale, 0.0);
  EXPECT_LT((rates.force - plain.force).cwiseAbs().maxCoeff(), 1e-12 * force_scale);
  EXPECT_LT((rates.drho_dt - plain.drho).cwiseAbs().maxCoeff(), 1e-12 * drho_scale);
  ASSERT_GT(plain.viscous_loss_W, 0.0);  // the viscous force dissipates: the test below can fail
  EXPECT_NEAR(rates.viscous_loss_W, plain.viscous_loss_W, 1e-12 * plain.viscous_loss_W);
  for (Eigen::Index i = 0; i < f.size(); ++i) EXPECT_DOUBLE_EQ(rates.pressure[i], eos.pressure(f.rho[i])) << i;
}

TEST(FluidPairs, LanesAgreeWithAPlainSumOverEveryPair) {
  const double dx = 7.7e-6, viscosity = 0.1;
  const ListedFluid fluid(7, dx, 21);
  const auto& [f, kernel, lists, eos] = std::tie(fluid.f, fluid.kernel, fluid.lists, fluid.eos);
  FluidRates rates;
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, viscosity, 1, rates);
  const PlainSums plain = plain_pair_sums(f, kernel, eos, viscosity);
  ASSERT_GT(plain.pairs_in_support, 2000);
  ASSERT_GT(lists.fluid_fluid().pairs, static_cast<std::size_t>(plain.pairs_in_support));  // the skin lists more
  expect_plain_sums(f, eos, rates, plain);
}

// delta-SPH's density diffusion in the lanes against the plain sum, and it moves density between particles
// without creating any: sum of V_i d(rho_i)/dt is unchanged by it.
TEST(FluidPairs, DensityDiffusionAgreesWithAPlainSumAndCreatesNoDensity) {
  const double dx = 7.7e-6, viscosity = 0.1, diffusion = 0.1 * 1.3 * dx * 374.0;  // delta h c0
  const ListedFluid fluid(7, dx, 5);
  const auto& [f, kernel, lists, eos] = std::tie(fluid.f, fluid.kernel, fluid.lists, fluid.eos);
  FluidRates with, without;
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, viscosity, 1, with, diffusion);
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, viscosity, 1, without);
  expect_plain_sums(f, eos, with, plain_pair_sums(f, kernel, eos, viscosity, diffusion));
  const Eigen::VectorXd volume = f.m.cwiseQuotient(f.rho), added = with.drho_dt - without.drho_dt;
  ASSERT_GT(added.cwiseAbs().maxCoeff(), 1e-3 * without.drho_dt.cwiseAbs().maxCoeff());  // it does something
  EXPECT_LT(std::abs(volume.dot(added)), 1e-10 * volume.cwiseProduct(added).cwiseAbs().sum());
  EXPECT_EQ((with.force - without.force).cwiseAbs().maxCoeff(), 0.0);  // forces untouched
}

// The density drift's two passes (PairTerms::Continuity, then Forces) give what the one pass gives: the
// continuity pass the density rates (with delta-SPH) and zero forces, the force pass the forces and the
// viscous loss and zero density rates.
TEST(FluidPairs, TheContinuityAndForcePassesSplitTheOnePass) {
  const double dx = 7.7e-6, viscosity = 0.1, diffusion = 0.1 * 1.3 * dx * 374.0;
  const ListedFluid fluid(7, dx, 9);
  const auto& [f, kernel, lists, eos] = std::tie(fluid.f, fluid.kernel, fluid.lists, fluid.eos);
  FluidRates all, continuity, forces;
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, viscosity, 1, all, diffusion);
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, viscosity, 1, continuity, diffusion, PairTerms::Continuity);
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, viscosity, 1, forces, diffusion, PairTerms::Forces);
  const double rate_scale = all.drho_dt.cwiseAbs().maxCoeff(), force_scale = all.force.cwiseAbs().maxCoeff();
  ASSERT_GT(rate_scale, 0);
  ASSERT_GT(force_scale, 0);
  EXPECT_LT((continuity.drho_dt - all.drho_dt).cwiseAbs().maxCoeff(), 1e-12 * rate_scale);
  EXPECT_LT((forces.force - all.force).cwiseAbs().maxCoeff(), 1e-12 * force_scale);
  EXPECT_EQ(continuity.force.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(forces.drho_dt.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_NEAR(forces.viscous_loss_W, all.viscous_loss_W, 1e-12 * std::abs(all.viscous_loss_W));
  EXPECT_EQ(continuity.viscous_loss_W, 0.0);
  EXPECT_NEAR(continuity.density_diffusion_W, all.density_diffusion_W, 1e-12 * std::abs(all.density_diffusion_W));
  EXPECT_EQ(forces.density_diffusion_W, 0.0);
}

// The force pass of the density drift takes each pair's kernel gradient from the continuity pass just
// before it (the same positions and h) instead of computing it again: the same bits, on one thread and
// on two (each block reads only its own rows' slots).
TEST(FluidPairs, TheForcePassOnTheContinuityPassesGradientsGivesTheSameBits) {
  const double dx = 7.7e-6, viscosity = 0.1;
  const ListedFluid fluid(9, dx, 4);
  const auto& [f, kernel, lists, eos] = std::tie(fluid.f, fluid.kernel, fluid.lists, fluid.eos);
  for (int threads : {1, 2}) {
    if (threads > 1 && !built_with_openmp()) continue;
    FluidRates continuity, computed, reused;
    fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, viscosity, threads, continuity, 0.0, PairTerms::Continuity);
    ASSERT_EQ(continuity.pair_gradient.size(), lists.fluid_fluid().index.size());
    fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, viscosity, threads, computed, 0.0, PairTerms::Forces);
    fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, viscosity, threads, reused, 0.0, PairTerms::Forces,
                     &continuity);
    ASSERT_GT(computed.force.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_TRUE((reused.force.array() == computed.force.array()).all()) << threads << " threads";
    EXPECT_EQ(reused.viscous_loss_W, computed.viscous_loss_W) << threads << " threads";
    // Gradients of another state (the pairs moved) give other forces: the pass does read them.
    FluidParticles moved = f;
    moved.x *= 1.01;
    FluidRates other, stale;
    fluid_pair_terms(moved, lists.fluid_fluid(), kernel, eos, viscosity, threads, other, 0.0, PairTerms::Continuity);
    fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, viscosity, threads, stale, 0.0, PairTerms::Forces,
                     &other);
    EXPECT_GT((stale.force - computed.force).cwiseAbs().maxCoeff(), 1e-3 * computed.force.cwiseAbs().maxCoeff());
  }
}

// Rows go 256 at a time, each chunk writing the records its pairs reach just before it; a thread's
// pairs also reach the next block's first records, written before the barrier. With blocks of many
// chunks every record must still be written before it is read, and every sum zeroed before it adds.
TEST(FluidPairs, ChunksOfRowsInEveryThreadBlockAgreeWithAPlainSum) {
  const double dx = 7.7e-6, viscosity = 0.1;
  const ListedFluid fluid(14, dx, 3);  // 2744 particles: 4 blocks of 2-3 chunks
  const auto& [f, kernel, lists, eos] = std::tie(fluid.f, fluid.kernel, fluid.lists, fluid.eos);
  const PlainSums plain = plain_pair_sums(f, kernel, eos, viscosity);
  // One block; four blocks on four threads; four on one thread, in turn (block 0 reads block 1's
  // first records before block 1 runs, so they must have been written before the barrier).
  for (const auto& [threads, on_one_thread] : {std::pair{1, false}, std::pair{4, false}, std::pair{4, true}}) {
    if (threads > 1 && !built_with_openmp()) continue;
#ifdef _OPENMP
    const int levels = omp_get_max_active_levels();
    if (on_one_thread) omp_set_max_active_levels(0);
#endif
    FluidRates rates;
    // A record read before it is written, or a sum added to before it is zeroed, shows as NaN.
    rates.records.setConstant(12, f.size() + 1, std::nan(""));
    rates.thread_sums.assign(static_cast<std::size_t>(threads), Eigen::Matrix4Xd::Constant(4, f.size() + 1, std::nan("")));
    fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, viscosity, threads, rates);
#ifdef _OPENMP
    omp_set_max_active_levels(levels);
#endif
    SCOPED_TRACE(std::to_string(threads) + (on_one_thread ? " blocks on one thread" : " blocks"));
    expect_plain_sums(f, eos, rates, plain);
  }
}

TEST(FluidPairs, ListRowsArePaddedToWholeLanesWithAnIndexPastTheFluid) {
  const double dx = 7.7e-6;
  const FluidParticles f = random_fluid(5, dx, 3);
  NeighbourLists lists(0.2 * dx);
  lists.update(f.x, Eigen::Matrix3Xd(3, 0), 2.6 * dx, 0.0);
  const PairList& list = lists.fluid_fluid();
  const int n = static_cast<int>(f.size());
  std::size_t real = 0, padding = 0;
  for (int i = 0; i < list.rows(); ++i) {
    EXPECT_EQ((list.offset[i + 1] - list.offset[i]) % kPairLanes, 0) << "row " << i;
    int row_padding = 0;
    for (int q = list.offset[i]; q < list.offset[i + 1]; ++q) {
      const int j = list.index[q];
      if (j == n) {
        ++row_padding;
        continue;
      }
      ++real;
      EXPECT_GT(j, i);
      EXPECT_EQ(row_padding, 0) << "row " << i << ": padding only at the end";
    }
    EXPECT_LT(row_padding, kPairLanes) << "row " << i;
    padding += static_cast<std::size_t>(row_padding);
  }
  EXPECT_EQ(list.pairs, real);
  EXPECT_GT(padding, 0u);
}

TEST(FluidPairs, ThreadsAgreeToRoundOffAndEachCountIsReproducible) {
  if (!built_with_openmp()) GTEST_SKIP() << "built without OpenMP: only one thread";
  const double dx = 7.7e-6;
  const ListedFluid fluid(9, dx, 5);
  const auto& [f, kernel, lists, eos] = std::tie(fluid.f, fluid.kernel, fluid.lists, fluid.eos);
  FluidRates one, three, three_again;
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, 0.1, 1, one);
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, 0.1, 3, three);
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, 0.1, 3, three_again);
  EXPECT_TRUE(three.force == three_again.force && three.drho_dt == three_again.drho_dt);  // bit for bit
  const double force_scale = one.force.colwise().norm().maxCoeff(), drho_scale = one.drho_dt.cwiseAbs().maxCoeff();
  EXPECT_LT((three.force - one.force).cwiseAbs().maxCoeff(), 1e-12 * force_scale);
  EXPECT_LT((three.drho_dt - one.drho_dt).cwiseAbs().maxCoeff(), 1e-12 * drho_scale);
  EXPECT_FALSE(three.force == one.force) << "the threads' sums were not used (or the split is trivial)";
#ifdef _OPENMP
  // If the runtime grants fewer threads than asked, every block still runs, with the same result.
  const int levels = omp_get_max_active_levels();
  omp_set_max_active_levels(0);  // parallel regions run on one thread
  FluidRates three_on_one;
  fluid_pair_terms(f, lists.fluid_fluid(), kernel, eos, 0.1, 3, three_on_one);
  omp_set_max_active_levels(levels);
  EXPECT_TRUE(three_on_one.force == three.force && three_on_one.drho_dt == three.drho_dt);
#endif
}
