#pragma once
// How the start and the drying of a run went: written as attributes of every result file, and
// carried from a dried state into the compressions that continue from it (--from).
#include <cmath>
#include <sstream>
#include <string>

#include "core/energy_terms.hpp"

#include "engine/settle.hpp"

namespace cellsim {

struct DryingSummary {
  SettleReport settle;
  bool dried = true;                // a drying stage ran (here or in the state continued from); not so
                                    // for a cell only settled (drying.steps = 0), which has no cap to hit
  bool steady = false;              // drying ended at steady state (steady_state.hpp), not at its cap
  double steady_time_s = std::nan("");  // simulated time at which it did
  // The cell's volumetric modulus V dP/dV at the end of drying (engine/volumetric_modulus.hpp; closed
  // cells only, NaN for SPH).
  double volumetric_modulus_Pa = std::nan("");
  // The energy account's residual at the end of drying over the energy that flowed since t = 0
  // (engine/energy_account.hpp: residual_over_flows); NaN where no drying ran.
  double energy_residual_share = std::nan("");

  // The warning a run, its file and the report show when drying hit its cap unsteady.
  std::string warning() const {
    std::string w;
    if (dried && !steady) w += "drying reached drying.steps without a steady state; ";
    if (settle.iterations > 0 && !settle.converged) w += "the relaxation at rest stopped at settle.max_iterations; ";
    if (std::abs(energy_residual_share) > kEnergyResidualTolerance) {
      std::ostringstream open;
      open << "energy account: drying's residual is " << 100 * energy_residual_share
           << " % of the energy that flowed (tolerance " << 100 * kEnergyResidualTolerance << " %); ";
      w += open.str();
    }
    return w.empty() ? w : w.substr(0, w.size() - 2);
  }
};

}  // namespace cellsim
