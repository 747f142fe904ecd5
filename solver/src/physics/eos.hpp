#pragma once
// Equation of state, Eq 7: P = P_T + K [(rho/rho0)^gamma - 1] (gauge pressure, outside = 0).
#include <cmath>

namespace cellsim {

struct EquationOfState {
  double turgor_Pa;        // P_T(X) = P_T0 X (model.md §5)
  double bulk_modulus_Pa;  // K
  double rho0_kg_m3;
  double exponent;         // 7

  double pressure(double rho) const {
    const double ratio = rho / rho0_kg_m3;
    // gamma = 7 in practice: integer powers avoid std::pow on the hot path.
    const double p = exponent == 7.0 ? ratio * ratio * ratio * ratio * ratio * ratio * ratio
                                     : std::pow(ratio, exponent);
    return turgor_Pa + bulk_modulus_Pa * (p - 1.0);
  }
  double sound_speed_m_s() const { return std::sqrt(exponent * bulk_modulus_Pa / rho0_kg_m3); }
};

}  // namespace cellsim
