#include "fluid_pairs.hpp"

#include <cassert>
#include <cmath>

#include "simd4.hpp"
#include "sph_terms.hpp"

namespace cellsim {
namespace {

using simd::double4;

// Where the padding index n of the pair list points: a particle far beyond any kernel support, at
// rest, without mass, so that its lanes add exact zeros.
constexpr double kFarAway_m = 1e30;

// One record of 16 doubles per particle (columns 0..n-1, and column n for the padding index),
// four fields of four: position (x, 0), velocity (v, 0), factors (m, P/rho^2, m/rho, 0) and the
// sums the pairs add up (force, drho/dt). One record per particle keeps each particle's data in
// two adjacent cache lines and never puts a field that is read at the address offset of one written.
enum Field : int { kPosition = 0, kVelocity = 4, kFactors = 8, kSums = 12, kRecord = 16 };

void fill_records(const FluidParticles& f, const EquationOfState& eos, FluidRates& out) {
  const Eigen::Index n = f.size();
  out.pressure.resize(n);
  out.records.setZero(kRecord, n + 1);
  for (Eigen::Index i = 0; i < n; ++i) {
    out.pressure[i] = eos.pressure(f.rho[i]);
    auto r = out.records.col(i);
    r.segment<3>(kPosition) = f.x.col(i);
    r.segment<3>(kVelocity) = f.v.col(i);
    r.segment<3>(kFactors) << f.m[i], out.pressure[i] / (f.rho[i] * f.rho[i]), f.m[i] / f.rho[i];
  }
  out.records.col(n).segment<3>(kPosition).setConstant(kFarAway_m);
}

// Four records, transposed: lane l of field k is row l's entry k.
struct Lanes {
  double4 field[4];
  Lanes(double4 a, double4 b, double4 c, double4 d) : field{a, b, c, d} {
    simd::transpose(field[0], field[1], field[2], field[3]);
  }
};

}  // namespace

// Each pair of the half list is visited once and applied to both particles, with the per-pair
// physics of sph_terms.hpp (Eqs 3, 4, 10), four pairs of a row at a time (one per lane). Pairs
// beyond the kernel support (the list has a skin) and padding get g = 0 and add exact zeros. The
// differences x_ij, v_ij are taken on the records, before the transpose: fewer registers stay live.
void fluid_pair_terms(const FluidParticles& f, const PairList& pairs, const CubicSplineKernel& kernel_of_step,
                      const EquationOfState& eos, double viscosity_Pa_s, FluidRates& out) {
  fill_records(f, eos, out);
  const CubicSplineKernel kernel = kernel_of_step;  // a local copy: the stores below cannot change it
  const int* offset = pairs.offset.data();
  const int* index = pairs.index.data();
  const double* position = out.records.data() + kPosition;
  const double* velocity = out.records.data() + kVelocity;
  const double* factors = out.records.data() + kFactors;
  double* sums = out.records.data() + kSums;
  const double4 mu_sum = simd::broadcast(2.0 * viscosity_Pa_s);  // mu_i + mu_j: one viscosity
  for (int i = 0; i < pairs.rows(); ++i) {
    const double4 x_i = simd::load(position + kRecord * i), v_i = simd::load(velocity + kRecord * i);
    const double4 mi = simd::broadcast(factors[kRecord * i]), Ai = simd::broadcast(factors[kRecord * i + 1]),
                  Vi = simd::broadcast(factors[kRecord * i + 2]);
    double4 sum_i = {}, drho_i = {};
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
      const double4 g = kernel.dW_dr_over_r(
          simd::sqrt(xij.field[0] * xij.field[0] + xij.field[1] * xij.field[1] + xij.field[2] * xij.field[2]));
      const double4 v_dot_grad =
          g * (vij.field[0] * xij.field[0] + vij.field[1] * xij.field[1] + vij.field[2] * xij.field[2]);
      drho_i += sph::continuity_rate(v_dot_grad, mj);
      const double4 pressure = g * sph::pressure_coefficient(mi, mj, Ai, Aj);
      const double4 viscous = g * sph::viscous_coefficient(mu_sum, Vi, Vj);
      // Transposed back, lane l is j's record (F_ij, -drho_j): subtracted from j's sums it gives
      // F_ji = -F_ij and adds drho_j; added to i's, its first three entries give F_ij.
      const Lanes on_j(pressure * xij.field[0] + viscous * vij.field[0],
                       pressure * xij.field[1] + viscous * vij.field[1],
                       pressure * xij.field[2] + viscous * vij.field[2], -sph::continuity_rate(v_dot_grad, mi));
      for (int l = 0; l < kPairLanes; ++l) {
        double* sum_j = sums + kRecord * j[l];
        simd::store(sum_j, simd::load(sum_j) - on_j.field[l]);
        sum_i += on_j.field[l];
      }
    }
    sum_i[3] = simd::sum(drho_i);
    simd::store(sums + kRecord * i, simd::load(sums + kRecord * i) + sum_i);
  }
  const Eigen::Index n = f.size();
  out.force = out.records.block(kSums, 0, 3, n);
  out.drho_dt = out.records.row(kSums + 3).head(n).transpose();
}

}  // namespace cellsim
