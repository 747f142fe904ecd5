#include "io/energy_terms_json.hpp"

#include <nlohmann/json.hpp>

#include "core/energy_terms.hpp"

namespace cellsim {

std::string energy_terms_json() {
  static const char* const kRoles[] = {"stored", "flow", "loss"};
  static const char* const kSources[] = {"state", "power", "density_power", "jump"};
  nlohmann::json terms = nlohmann::json::array();
  for (const EnergyTerm& term : kEnergyTerms) {
    terms.push_back({{"label", term.label},
                     {"column", term.column ? nlohmann::json(term.column) : nlohmann::json()},
                     {"unit", "J"},
                     {"role", kRoles[static_cast<int>(term.role)]},
                     {"residual_sign", residual_sign(term.role)},
                     {"source", kSources[static_cast<int>(term.source)]},
                     {"definition", term.definition}});
  }
  return terms.dump(2) + "\n";
}

}  // namespace cellsim
