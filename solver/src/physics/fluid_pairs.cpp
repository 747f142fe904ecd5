#include "physics/fluid_pairs.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <type_traits>

#include "parallel/simd4.hpp"
#include "parallel/threads.hpp"
#include "physics/sph_terms.hpp"

namespace cellsim {
namespace {

using simd::double4;

// Where the padding index n of the pair list points: a particle far beyond any kernel support, at
// rest, without mass, so that its lanes add exact zeros.
constexpr double kFarAway_m = 1e30;

// One record of 12 doubles per particle (columns 0..n-1, and column n for the padding index),
// three fields of four: position (x, 0), velocity (v, 0), factors (m, P/rho^2, m/rho, rho). The
// sums the pairs add up, (force, drho/dt), are records of four in a separate array per thread.
enum Field : int { kPosition = 0, kVelocity = 4, kFactors = 8, kRecord = 12, kSum = 4 };

// The records of particles [begin, end). A pass that uses no pressure (continuity without the
// diffusion's energy) computes none (the EOS is a seventh power) and writes P/rho^2 = 0.
void fill_records(const FluidParticles& f, const EquationOfState& eos, Eigen::Index begin, Eigen::Index end,
                  bool with_pressure, FluidRates& out) {
  for (Eigen::Index i = begin; i < end; ++i) {
    if (with_pressure) out.pressure[i] = eos.pressure(f.rho[i]);
    const double P_over_rho2 = with_pressure ? out.pressure[i] / (f.rho[i] * f.rho[i]) : 0.0,
                 volume = f.m[i] / f.rho[i];
    out.records.col(i) << f.x.col(i), 0.0, f.v.col(i), 0.0, f.m[i], P_over_rho2, volume, f.rho[i];
  }
}

// Four records, transposed: lane l of field k is row l's entry k.
struct Lanes {
  double4 field[4];
  Lanes(double4 a, double4 b, double4 c, double4 d) : field{a, b, c, d} {
    simd::transpose(field[0], field[1], field[2], field[3]);
  }
};

// Rows first_row[t] .. first_row[t + 1] - 1 go to thread t: the particles [n t / T, n (t + 1) / T)
// that every other loop of the step gives it too, so each thread works on memory it wrote itself
// (between cores, memory costs far more than a slightly uneven split of the pairs).
std::vector<int> split_rows(const PairList& pairs, int threads) {
  std::vector<int> first_row(static_cast<std::size_t>(threads) + 1);
  for (int t = 0; t <= threads; ++t)
    first_row[static_cast<std::size_t>(t)] = static_cast<int>(block_start(pairs.rows(), t, threads));
  return first_row;
}

// The pairs of rows [begin, end) added to sums, four pairs of a row at a time (one per lane), and the
// power their viscous forces dissipate added to viscous_loss (F_visc,ij . v_ij = viscous |v_ij|^2 <= 0
// is what the pair adds to the kinetic energy). The differences x_ij, v_ij are taken on the records,
// before the transpose: fewer registers stay live.
// kDiffusion: with the delta-SPH density diffusion (a separate loop: without it, nothing changes);
// kTerms: which terms (PairTerms), each set its own loop. A continuity pass writes each slot's kernel
// gradient g to gradient_out; a forces pass with kKnownGradient reads it from known_gradient instead.
template <bool kDiffusion, PairTerms kTerms, bool kKnownGradient>
void add_pair_terms(const PairList& pairs, const CubicSplineKernel& kernel_of_step, Viscosity viscosity,
                    double diffusion_m2_s, const double* records, int begin, int end, double* sums,
                    double& viscous_loss, double& diffusion_power, const double* known_gradient,
                    double* gradient_out) {
  const CubicSplineKernel kernel = kernel_of_step;  // a local copy: the stores below cannot change it
  const int* offset = pairs.offset.data();
  const int* index = pairs.index.data();
  const double* position = records + kPosition;
  const double* velocity = records + kVelocity;
  const double* factors = records + kFactors;
  const double4 uniform_mu_sum = simd::broadcast(2.0 * viscosity.uniform_Pa_s);  // mu_i + mu_j: one viscosity
  const double* mu = viscosity.per_particle_Pa_s;
  for (int i = begin; i < end; ++i) {
    const double4 mu_sum = mu ? simd::broadcast(2.0 * mu[i]) : uniform_mu_sum;  // i's and j's cell are one
    const double4 x_i = simd::load(position + kRecord * i), v_i = simd::load(velocity + kRecord * i);
    const double4 mi = simd::broadcast(factors[kRecord * i]), Ai = simd::broadcast(factors[kRecord * i + 1]),
                  Vi = simd::broadcast(factors[kRecord * i + 2]);
    [[maybe_unused]] const double4 rho_i = simd::broadcast(factors[kRecord * i + 3]),
                                   diffusion = simd::broadcast(diffusion_m2_s);
    double4 sum_i = {}, drho_i = {}, loss_i = {}, diffusion_power_i = {};
    assert((offset[i + 1] - offset[i]) % kPairLanes == 0);
    for (int q = offset[i]; q < offset[i + 1]; q += kPairLanes) {
      const int* j = index + q;
      const auto record = [&](const double* base, int l) { return simd::load(base + kRecord * j[l]); };
      const Lanes xij(x_i - record(position, 0), x_i - record(position, 1), x_i - record(position, 2),
                      x_i - record(position, 3));
      const Lanes vij(v_i - record(velocity, 0), v_i - record(velocity, 1), v_i - record(velocity, 2),
                      v_i - record(velocity, 3));
      const Lanes factors_j(record(factors, 0), record(factors, 1), record(factors, 2), record(factors, 3));
      const double4 mj = factors_j.field[0], Aj = factors_j.field[1], Vj = factors_j.field[2];
      constexpr bool kContinuity = kTerms != PairTerms::Forces, kForces = kTerms != PairTerms::Continuity;
      double4 g;
      if constexpr (kKnownGradient) {
        g = simd::load(known_gradient + q);
      } else {
        g = kernel.dW_dr_over_r(
            simd::sqrt(xij.field[0] * xij.field[0] + xij.field[1] * xij.field[1] + xij.field[2] * xij.field[2]));
        if constexpr (kTerms == PairTerms::Continuity) simd::store(gradient_out + q, g);
      }
      double4 minus_drho_j = {};  // on_j's last lane, taken from j's sums
      if constexpr (kContinuity) {
        const double4 v_dot_grad =
            g * (vij.field[0] * xij.field[0] + vij.field[1] * xij.field[1] + vij.field[2] * xij.field[2]);
        drho_i += sph::continuity_rate(v_dot_grad, mj);
        minus_drho_j = -sph::continuity_rate(v_dot_grad, mi);
      }
      if constexpr (kDiffusion && kContinuity) {
        const double4 rho_j = factors_j.field[3];
        const double4 to_i = sph::density_diffusion_rate(diffusion, g, rho_i, rho_j, Vj),
                      to_j = sph::density_diffusion_rate(diffusion, g, rho_j, rho_i, Vi);
        drho_i += to_i;
        minus_drho_j -= to_j;
        // the internal energy it moves: m P / rho^2 d(rho) for both (the energy account)
        diffusion_power_i += mi * Ai * to_i + mj * factors_j.field[1] * to_j;
      }
      double4 pressure = {}, viscous = {};
      if constexpr (kForces) {
        pressure = g * sph::pressure_coefficient(mi, mj, Ai, Aj);
        viscous = g * sph::viscous_coefficient(mu_sum, Vi, Vj);
        loss_i -= viscous * (vij.field[0] * vij.field[0] + vij.field[1] * vij.field[1] + vij.field[2] * vij.field[2]);
      }
      // Transposed back, lane l is j's record (F_ij, -drho_j): subtracted from j's sums it gives
      // F_ji = -F_ij and adds drho_j; added to i's, its first three entries give F_ij.
      const Lanes on_j(pressure * xij.field[0] + viscous * vij.field[0],
                       pressure * xij.field[1] + viscous * vij.field[1],
                       pressure * xij.field[2] + viscous * vij.field[2], minus_drho_j);
      for (int l = 0; l < kPairLanes; ++l) {
        double* sum_j = sums + kSum * j[l];
        simd::store(sum_j, simd::load(sum_j) - on_j.field[l]);
        sum_i += on_j.field[l];
      }
    }
    sum_i[3] = simd::sum(drho_i);
    simd::store(sums + kSum * i, simd::load(sums + kSum * i) + sum_i);
    viscous_loss += simd::sum(loss_i);
    if constexpr (kDiffusion) diffusion_power += simd::sum(diffusion_power_i);
  }
}

// The particles j >= last (but not the padding n) that rows [first, last) reach, ascending.
void find_halo(const PairList& pairs, int first, int last, std::vector<char>& mark, std::vector<int>& halo) {
  const int n = pairs.rows();
  mark.assign(static_cast<std::size_t>(n), 0);
  for (int q = pairs.offset[static_cast<std::size_t>(first)]; q < pairs.offset[static_cast<std::size_t>(last)]; ++q) {
    const int j = pairs.index[static_cast<std::size_t>(q)];
    if (j >= last && j < n) mark[static_cast<std::size_t>(j)] = 1;
  }
  halo.clear();
  for (int j = last; j < n; ++j)
    if (mark[static_cast<std::size_t>(j)]) halo.push_back(j);
}

// The last particle (not the padding n) that row i reaches, or i if none: a row is ascending, its
// padding (n) at the end.
int last_reached(const PairList& pairs, int i) {
  const int n = pairs.rows();
  for (int q = pairs.offset[static_cast<std::size_t>(i) + 1] - 1; q >= pairs.offset[static_cast<std::size_t>(i)]; --q)
    if (pairs.index[static_cast<std::size_t>(q)] < n) return pairs.index[static_cast<std::size_t>(q)];
  return i;
}

// One past the last record of block t that the pairs of blocks before it reach (their halos), or the
// block's first row if they reach none of it.
int reached_by_earlier_blocks(const FluidRates& out, int t) {
  const auto b = static_cast<std::size_t>(t);
  const int r0 = out.first_row[b], r1 = out.first_row[b + 1];
  int reached = r0;
  for (std::size_t s = 0; s < b; ++s) {
    const auto& halo = out.halo[s];
    const auto past = std::lower_bound(halo.begin(), halo.end(), r1);
    if (past != halo.begin() && *(past - 1) >= r0) reached = std::max(reached, *(past - 1) + 1);
  }
  return reached;
}

// Rows [r0, r1) of one block, a chunk at a time: each chunk first writes the records (from r0 on,
// those not written before the barrier: from `written`) and zeroes the sums its pairs reach, then
// adds its pairs. A record is thus written just before its first use and is still in cache when the
// pairs read it: a tissue's fluid is many times the cache (docs/performance.md). The sums see the
// same pairs in the same order, so the result does not change.
void add_block(const FluidParticles& f, const PairList& pairs, const CubicSplineKernel& kernel, const EquationOfState& eos,
               Viscosity viscosity, double diffusion_m2_s, PairTerms terms, const double* known_gradient,
               bool with_pressure, int r0, int r1, int written, FluidRates& out,
               Eigen::Matrix4Xd& sums, double& viscous_loss, double& diffusion_power) {
  constexpr int kChunkRows = 256;
  int zeroed = r0;
  for (int c0 = r0; c0 < r1; c0 += kChunkRows) {
    const int c1 = std::min(c0 + kChunkRows, r1);
    int reach = c1;  // one past the last particle the chunk's rows reach
    for (int i = c0; i < c1; ++i) reach = std::max(reach, last_reached(pairs, i) + 1);
    if (std::min(reach, r1) > written) {  // records past r1 are the next block's, written before the barrier
      fill_records(f, eos, written, std::min(reach, r1), with_pressure, out);
      written = std::min(reach, r1);
    }
    if (reach > zeroed) {
      sums.middleCols(zeroed, reach - zeroed).setZero();
      zeroed = reach;
    }
    const auto pass = [&](auto diffusion, auto terms, auto known) {
      add_pair_terms<decltype(diffusion)::value, decltype(terms)::value, decltype(known)::value>(
          pairs, kernel, viscosity, diffusion_m2_s, out.records.data(), c0, c1, sums.data(), viscous_loss,
          diffusion_power, known_gradient, out.pair_gradient.data());
    };
    using Off = std::false_type;
    using On = std::true_type;
    using All = std::integral_constant<PairTerms, PairTerms::All>;
    using Continuity = std::integral_constant<PairTerms, PairTerms::Continuity>;
    using Forces = std::integral_constant<PairTerms, PairTerms::Forces>;
    const bool diffusion = diffusion_m2_s != 0;
    if (terms == PairTerms::Forces)
      known_gradient ? pass(Off{}, Forces{}, On{}) : pass(Off{}, Forces{}, Off{});
    else if (terms == PairTerms::Continuity)
      diffusion ? pass(On{}, Continuity{}, Off{}) : pass(Off{}, Continuity{}, Off{});
    else
      diffusion ? pass(On{}, All{}, Off{}) : pass(Off{}, All{}, Off{});
  }
}

// The blocks' sums for particles [begin, end), added in block order: each block wrote (and zeroed)
// only its own rows and its halo.
void add_thread_sums(Eigen::Index begin, Eigen::Index end, FluidRates& out) {
  out.force.middleCols(begin, end - begin).setZero();
  out.drho_dt.segment(begin, end - begin).setZero();
  for (std::size_t t = 0; t < out.thread_sums.size(); ++t) {
    const auto& sums = out.thread_sums[t];
    const auto& halo = out.halo[t];
    for (auto j = std::lower_bound(halo.begin(), halo.end(), begin); j != halo.end() && *j < end; ++j) {
      out.force.col(*j) += sums.col(*j).head<3>();
      out.drho_dt[*j] += sums(3, *j);
    }
    const Eigen::Index from = std::max<Eigen::Index>(begin, out.first_row[t]),
                       to = std::min<Eigen::Index>(end, out.first_row[t + 1]);
    if (from >= to) continue;
    out.force.middleCols(from, to - from) += sums.block(0, from, 3, to - from);
    out.drho_dt.segment(from, to - from) += sums.row(3).segment(from, to - from).transpose();
  }
}

}  // namespace

// Each pair of the half list is visited once and applied to both particles, with the per-pair
// physics of sph_terms.hpp (Eqs 3, 4, 10). Pairs beyond the kernel support (the list has a skin)
// and padding get g = 0 and add exact zeros. The work is cut into `threads` blocks, each with its
// own sums, added up in block order at the end: the result depends on the block count only, even
// if the runtime runs the blocks on fewer threads than asked.
void fluid_pair_terms(const FluidParticles& f, const PairList& pairs, const CubicSplineKernel& kernel,
                      const EquationOfState& eos, Viscosity viscosity, int threads, FluidRates& out,
                      double density_diffusion_m2_s, PairTerms terms, const FluidRates* continuity_pass) {
  const Eigen::Index n = f.size();
  assert(!continuity_pass || (terms == PairTerms::Forces && continuity_pass->pair_gradient.size() == pairs.index.size()));
  const double* known_gradient = continuity_pass ? continuity_pass->pair_gradient.data() : nullptr;
  const bool with_pressure = terms != PairTerms::Continuity || density_diffusion_m2_s != 0;
  if (terms == PairTerms::Continuity) out.pair_gradient.resize(pairs.index.size());
  out.pressure.resize(n);
  out.records.resize(kRecord, n + 1);
  out.thread_sums.resize(static_cast<std::size_t>(threads));
  out.first_row = split_rows(pairs, threads);
  const bool new_halos = pairs.build == 0 || out.halo_build != pairs.build ||  // 0: a list not built by NeighbourLists
                         out.halo.size() != static_cast<std::size_t>(threads);
  out.halo.resize(static_cast<std::size_t>(threads));
  out.halo_mark.resize(static_cast<std::size_t>(threads));
  out.halo_build = pairs.build;
  out.written.resize(static_cast<std::size_t>(threads));
  out.block_viscous_loss_W.assign(static_cast<std::size_t>(threads), 0.0);
  out.block_diffusion_W.assign(static_cast<std::size_t>(threads), 0.0);
  const auto run_blocks = [&](int first, int stride) {
    if (new_halos) {
      for (int t = first; t < threads; t += stride) {
        const auto b = static_cast<std::size_t>(t);
        find_halo(pairs, out.first_row[b], out.first_row[b + 1], out.halo_mark[b], out.halo[b]);
      }
      if (stride > 1) wait_for_all_threads();  // each block reads the halos of the blocks before it
    }
    // Before the barrier, each block writes the records that earlier blocks' pairs reach, and the
    // last block the padding record; each zeroes its sums' padding column (the rest go chunk by chunk).
    for (int t = first; t < threads; t += stride) {
      const auto b = static_cast<std::size_t>(t);
      const int r0 = out.first_row[b], r1 = out.first_row[b + 1];
      const int reached = reached_by_earlier_blocks(out, t);
      fill_records(f, eos, r0, reached, with_pressure, out);
      out.written[b] = reached;
      if (r1 == n) {
        out.records.col(n).setZero();
        out.records.col(n).segment<3>(kPosition).setConstant(kFarAway_m);
      }
      auto& sums = out.thread_sums[b];
      sums.resize(kSum, n + 1);
      sums.col(n).setZero();
    }
    if (stride > 1) wait_for_all_threads();  // every record another block reads is written
    for (int t = first; t < threads; t += stride) {
      const auto b = static_cast<std::size_t>(t);
      add_block(f, pairs, kernel, eos, viscosity, density_diffusion_m2_s, terms, known_gradient, with_pressure,
                out.first_row[b], out.first_row[b + 1], out.written[b],
                out, out.thread_sums[b], out.block_viscous_loss_W[b], out.block_diffusion_W[b]);
    }
  };
  if (threads == 1)
    run_blocks(0, 1);
  else
    run_on_threads(threads, run_blocks);
  out.force.resize(3, n);
  out.drho_dt.resize(n);
  for_blocks(threads, n, [&](Eigen::Index begin, Eigen::Index end) { add_thread_sums(begin, end, out); });
  out.viscous_loss_W = out.density_diffusion_W = 0;
  for (double part : out.block_viscous_loss_W) out.viscous_loss_W += part;
  for (double part : out.block_diffusion_W) out.density_diffusion_W += part;
}

}  // namespace cellsim
