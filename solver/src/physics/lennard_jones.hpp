#pragma once
// Wall-fluid Lennard-Jones-type coupling, Eqs 12-13 and 17-19 (model.md §4):
// F_ik = f(r) x_ik on fluid i, x_ik = x_i - x_k (a position vector, not a unit vector),
// f(r) = f0 [(r0/r)^8 - (r0/r)^4] / r^2, with f0 = repulsion_f0 for r < r0 (f > 0, pushes i away)
// and f0 = attraction_f0 for r0 <= r < r_c (f < 0, pulls i back), 0 beyond r_c.
namespace cellsim {

struct LennardJones {
  double r0_m, cutoff_m, repulsion_f0_N_m, attraction_f0_N_m;

  // f(r) from r^2; powers of (r0/r)^2 avoid pow and sqrt. Branch-free (both strengths and the
  // cut-off are selects) so that a loop over pairs vectorises.
  double f_of_r2(double r2) const {
    const double inv_r2 = 1.0 / r2;
    const double q = r0_m * r0_m * inv_r2;  // (r0/r)^2
    const double q2 = q * q;
    const double f0 = q > 1.0 ? repulsion_f0_N_m : attraction_f0_N_m;
    const double f = f0 * (q2 * q2 - q2) * inv_r2;
    return r2 < cutoff_m * cutoff_m ? f : 0.0;
  }

  // The potential phi(r) of this force (-dphi/dr = f r, the energy account): f0 G(q) with
  // G(q) = q^4 / 8 - q^2 / 4, q = (r0/r)^2, shifted to zero at the cut-off and continuous at r0:
  // attraction f0_a (G(q) - G(q_c)); repulsion f0_r (G(q) - G(1)) + f0_a (G(1) - G(q_c)), q_c = (r0/r_c)^2.
  double potential_J(double r2) const {
    const double rc2 = cutoff_m * cutoff_m;
    if (r2 >= rc2) return 0.0;
    const auto G = [](double q) { return 0.125 * q * q * q * q - 0.25 * q * q; };
    const double r0_2 = r0_m * r0_m, q = r0_2 / r2, q_c = r0_2 / rc2;
    if (q <= 1.0) return attraction_f0_N_m * (G(q) - G(q_c));
    return repulsion_f0_N_m * (G(q) - G(1.0)) + attraction_f0_N_m * (G(1.0) - G(q_c));
  }
};

}  // namespace cellsim
