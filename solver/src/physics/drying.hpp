#pragma once
// What drying ramps (model.md §5, docs/model-closures.md): from the fresh cell at rest, the
// contraction rest length L_ref and the turgor P_T follow one smoothstep from their fresh values
// to those of the dryness X = X/X0, over drying.ramp_time_us.
namespace cellsim::drying {

// 0 at t = 0, 1 from ramp_time on, with zero slope at both ends.
inline double smoothstep_ramp(double t, double ramp_time) {
  if (ramp_time <= 0 || t >= ramp_time) return 1.0;
  const double u = t / ramp_time;
  return u * u * (3.0 - 2.0 * u);
}

// d(ramp)/dt: 6 u (1 - u) / ramp_time during the ramp, 0 after it.
inline double smoothstep_ramp_rate(double t, double ramp_time) {
  if (ramp_time <= 0 || t >= ramp_time) return 0.0;
  const double u = t / ramp_time;
  return 6.0 * u * (1.0 - u) / ramp_time;
}

// P_T at drying progress `ramp` in [0, 1]: P_T0 fresh, P_T(X) = P_T0 X at the end (model.md §5).
// A jump from P_T0 to P_T(X) at t = 0 would drop every particle's pressure at once and shock the
// settled cell as the old start did; the osmotic potential follows it (Pi = -P_T).
inline double turgor_Pa(double fresh_turgor_Pa, double dryness, double ramp) {
  return fresh_turgor_Pa * (1.0 - (1.0 - dryness) * ramp);
}

}  // namespace cellsim::drying
