#include "engine/energy_account.hpp"

#include <cmath>

namespace cellsim {

double stored_energy_J(const EnergyValues& terms) {
  double total = 0;
  for (const EnergyTerm& term : kEnergyTerms)
    if (term.role == EnergyRole::Stored) total += terms[term.id];
  return total;
}

void add_half_kick(const EnergyValues& power_W, double half_dt, bool density_flows, EnergyFlows& flows) {
  for (const EnergyTerm& term : kEnergyTerms)
    if (term.source == EnergySource::Power || (density_flows && term.source == EnergySource::DensityPower))
      flows.integral[term.id] += half_dt * power_W[term.id];
}

double drive_power_W(double stored_energy_per_turgor_m3, double turgor_rate_Pa_s, double contraction_times_l0_N_m,
                     double L_ref_shortening_rate_1_s) {
  return turgor_rate_Pa_s * stored_energy_per_turgor_m3 + L_ref_shortening_rate_1_s * contraction_times_l0_N_m;
}

double energy_residual_J(const EnergyValues& terms, double initial_J) {
  double put_in = 0;
  for (const EnergyTerm& term : kEnergyTerms)
    if (term.role != EnergyRole::Stored) put_in += residual_sign(term.role) * terms[term.id];
  return stored_energy_J(terms) - initial_J - put_in;
}

double residual_over_flows(const EnergyValues& terms, double residual_J) {
  double flowed = 0;
  for (const EnergyTerm& term : kEnergyTerms)
    if (term.role != EnergyRole::Stored) flowed += std::abs(terms[term.id]);
  return flowed > 0 ? residual_J / flowed : std::nan("");
}

}  // namespace cellsim
