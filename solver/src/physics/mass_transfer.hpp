#pragma once
// Mass transfer across the wall, Eq 11: dm_i/dt = -(A_c L_p rho_i / n_f)(P_i + Pi),
// osmotic potential Pi = -P_T(X) (model.md §5). Positive P_i + Pi: water leaves.
namespace cellsim {

inline double mass_rate(double wall_area_m2, double Lp_m_per_s_Pa, double rho, int n_fluid, double pressure_Pa,
                        double osmotic_Pa) {
  return -(wall_area_m2 * Lp_m_per_s_Pa * rho / n_fluid) * (pressure_Pa + osmotic_Pa);
}

// Energy per mass that Eq 11's water takes across the wall: a particle's mass changes at fixed volume
// m/rho (Eq 9), so its energy m (v^2/2 + e) changes by dm (v^2/2 + e + P/rho), the kinetic energy and
// the enthalpy (eos.hpp) of the water (the energy account).
inline double carried_energy_J_kg(double v2, double enthalpy_J_kg) { return 0.5 * v2 + enthalpy_J_kg; }

// Continuity with mass change, Eq 9: d(rho_i)/dt = d(rho_i*)/dt + (rho_i/m_i) dm_i/dt.
inline double density_rate(double continuity_rate, double rho, double m, double dm_dt) {
  return continuity_rate + rho / m * dm_dt;
}

}  // namespace cellsim
