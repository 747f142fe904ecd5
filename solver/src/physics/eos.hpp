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

  // Internal energy per mass, e(rho) = integral of P / rho^2 from rho0 (so de = P / rho^2 drho, the
  // work the pressure of Eq 7 does): (P_T - K)(1/rho0 - 1/rho) + K / (rho0 (gamma - 1)) ((rho/rho0)^(gamma-1) - 1).
  double internal_energy_J_kg(double rho) const {
    const double ratio = rho / rho0_kg_m3;
    const double p = exponent == 7.0 ? ratio * ratio * ratio * ratio * ratio * ratio : std::pow(ratio, exponent - 1.0);
    return (turgor_Pa - bulk_modulus_Pa) * (1.0 / rho0_kg_m3 - 1.0 / rho) +
           bulk_modulus_Pa / (rho0_kg_m3 * (exponent - 1.0)) * (p - 1.0);
  }
  // Enthalpy per mass e + P/rho: the P_T - K terms in 1/rho cancel, and K (rho/rho0)^gamma / rho =
  // (K/rho0)(rho/rho0)^(gamma-1), so a loop over particles needs no division (the factors are set once).
  struct Enthalpy {
    double offset_J_kg, scale_J_kg, inv_rho0, exponent_minus_1, inv_exponent_minus_1;
    double operator()(double rho) const {
      const double ratio = rho * inv_rho0;
      const double p = exponent_minus_1 == 6.0 ? ratio * ratio * ratio * ratio * ratio * ratio
                                               : std::pow(ratio, exponent_minus_1);
      return offset_J_kg + scale_J_kg * ((p - 1.0) * inv_exponent_minus_1 + p);
    }
  };
  Enthalpy enthalpy() const {
    return {(turgor_Pa - bulk_modulus_Pa) / rho0_kg_m3, bulk_modulus_Pa / rho0_kg_m3, 1.0 / rho0_kg_m3,
            exponent - 1.0, 1.0 / (exponent - 1.0)};
  }
  // d e / d P_T at fixed rho: how the drying's turgor ramp changes the stored energy.
  double internal_energy_per_turgor(double rho) const { return 1.0 / rho0_kg_m3 - 1.0 / rho; }
};

}  // namespace cellsim
