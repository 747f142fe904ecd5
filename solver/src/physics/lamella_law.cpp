// The middle-lamella law of a case (lamella_law.hpp).
#include "physics/lamella_law.hpp"

#include <sstream>

#include "core/errors.hpp"

namespace cellsim {

LamellaLaw make_lamella_law(const Params& p, double wall_particle_area_m2) {
  LamellaLaw law;
  law.stiffness_N_m = p.lamella_stiffness_N_m;
  law.peak_force_N = p.lamella_strength_Pa * wall_particle_area_m2;
  law.break_opening_m =
      lamella_break_opening_m(p.lamella_fracture_energy_J_m2, wall_particle_area_m2, law.peak_force_N);
  if (p.lamella_fracture_energy_J_m2 > 0 && law.peak_force_N > 0 && law.break_opening_m <= law.elastic_limit_m()) {
    const double least = law.peak_force_N * law.elastic_limit_m() / (2.0 * wall_particle_area_m2);
    std::ostringstream msg;
    msg << "tissue.lamella_fracture_energy_J_m2 = " << p.lamella_fracture_energy_J_m2
        << " is less than the elastic energy a bond holds at its peak tension (" << least
        << " J/m^2 with this strength and stiffness): give more, or 0 for a brittle bond";
    throw InputError(msg.str());
  }
  return law;
}

}  // namespace cellsim
