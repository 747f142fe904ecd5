#pragma once
// How the compression of a run ended: at the end it was asked for (compression.end_strain, or a
// load-unload's return off the top plate), or at its cap (compression.steps) before it. Written as
// attributes of the result file beside the drying summary; a stage that stopped short says so in the
// file's warning, in the log and in the summary table.
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

#include "core/energy_terms.hpp"

namespace cellsim {

struct CompressionSummary {
  bool ran = false;          // a compression stage ran in this run
  std::string asked;         // the end it was asked for, e.g. "compression.end_strain = 0.12"; empty: its steps
  bool reached = true;       // it ended there, not at its cap
  std::int64_t cap_steps = 0;  // compression.steps
  double strain = std::nan("");  // nominal strain when it ended
  // The energy account's residual gathered over the compression, over the plate work (NaN without work);
  // past kEnergyResidualTolerance the warning says the account is open.
  double energy_residual_share = std::nan("");

  // 1 reached its end, 0 stopped at its cap before it, -1 no end asked (or no compression).
  std::int64_t reached_code() const { return !ran || asked.empty() ? -1 : reached ? 1 : 0; }

  std::string warning() const {
    std::ostringstream w;
    if (reached_code() == 0)
      w << "compression reached compression.steps = " << cap_steps << " at nominal strain " << strain << " before "
        << asked;
    if (std::abs(energy_residual_share) > kEnergyResidualTolerance)
      w << (reached_code() == 0 ? "; " : "") << "energy account: compression's residual is "
        << 100 * energy_residual_share << " % of the plate work (tolerance " << 100 * kEnergyResidualTolerance << " %)";
    return w.str();
  }
};

}  // namespace cellsim
