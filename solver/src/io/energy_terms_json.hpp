#pragma once
// The energy account's table of terms (core/energy_terms.hpp) as JSON, for `cellsim energy-terms` and
// config/schema/energy_terms.json, which the workflow's aggregation reads (analysis/aggregate.py).
#include <string>

namespace cellsim {

std::string energy_terms_json();

}  // namespace cellsim
