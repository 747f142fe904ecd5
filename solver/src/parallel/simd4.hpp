#pragma once
// Four doubles in one register (GCC/Clang vector extensions: AVX with -march=x86-64-v3, two SSE2
// halves without it), and the few operations the fluid pair loop needs beyond + - * /.
// The pair loop handles four pairs at once: their particle records are loaded as rows and
// transposed into lanes (one lane per pair), which is much cheaper than gathering each field.
#include <cmath>
#include <cstring>

namespace cellsim::simd {

using double4 = double __attribute__((vector_size(32)));

inline double4 broadcast(double a) { return double4{a, a, a, a}; }

inline double4 load(const double* p) {
  double4 v;
  std::memcpy(&v, p, sizeof v);  // an unaligned vector load
  return v;
}

inline void store(double* p, double4 v) { std::memcpy(p, &v, sizeof v); }

inline double4 sqrt(double4 a) {
  return double4{std::sqrt(a[0]), std::sqrt(a[1]), std::sqrt(a[2]), std::sqrt(a[3])};  // one packed sqrt
}
inline double sqrt(double a) { return std::sqrt(a); }

inline double4 max(double4 a, double b) { return a > b ? a : broadcast(b); }
inline double max(double a, double b) { return a > b ? a : b; }
inline double4 min(double4 a, double b) { return a < b ? a : broadcast(b); }
inline double min(double a, double b) { return a < b ? a : b; }

// Lane-wise |a|.
inline double4 abs(double4 a) { return a < 0.0 ? -a : a; }
inline double abs(double a) { return a < 0.0 ? -a : a; }

// Lane-wise `condition ? a : b`, for a lane-wise comparison (all bits set where true).
template <class Mask>
double4 select(Mask condition, double4 a, double4 b) {
  return condition ? a : b;
}
inline double select(bool condition, double a, double b) { return condition ? a : b; }

// The 4x4 transpose: rows a, b, c, d (one record each) become columns (one field each), in place.
inline void transpose(double4& a, double4& b, double4& c, double4& d) {
  const double4 ab_even = __builtin_shufflevector(a, b, 0, 4, 2, 6), ab_odd = __builtin_shufflevector(a, b, 1, 5, 3, 7);
  const double4 cd_even = __builtin_shufflevector(c, d, 0, 4, 2, 6), cd_odd = __builtin_shufflevector(c, d, 1, 5, 3, 7);
  a = __builtin_shufflevector(ab_even, cd_even, 0, 1, 4, 5);
  b = __builtin_shufflevector(ab_odd, cd_odd, 0, 1, 4, 5);
  c = __builtin_shufflevector(ab_even, cd_even, 2, 3, 6, 7);
  d = __builtin_shufflevector(ab_odd, cd_odd, 2, 3, 6, 7);
}

// Sum of the four lanes in a fixed order, (a0 + a1) + (a2 + a3): deterministic.
inline double sum(double4 a) { return (a[0] + a[1]) + (a[2] + a[3]); }

}  // namespace cellsim::simd
