#pragma once
// The case-file schema: one row per JSON key, with unit, default, allowed range, meaning and
// equation. It drives validation, the defaults, `cellsim params` and docs/case-reference.md.
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "params.hpp"

namespace cellsim {

using ParamMember = std::variant<double Params::*, std::int64_t Params::*, std::optional<double> Params::*>;

struct ParamSpec {
  std::string key;          // JSON path, e.g. "wall.G_MPa"
  std::string unit;         // unit of the JSON value ("1" when dimensionless)
  double to_si;             // factor from the JSON unit to the SI member
  ParamMember member;
  std::optional<double> default_value;  // in JSON units; empty: derived ("auto"), see auto_rule
  double min, max;          // allowed range in JSON units
  bool min_inclusive, max_inclusive;
  std::string meaning;
  std::string equation;     // where the parameter enters the model
  std::string auto_rule;    // how an absent (or null) derived value is computed
};

const std::vector<ParamSpec>& param_specs();
const ParamSpec* find_param(const std::string& key);

bool is_integer(const ParamSpec& spec);
bool is_optional(const ParamSpec& spec);

// "0 < value <= 1", as shown in error messages and the reference table.
std::string describe_range(const ParamSpec& spec);

// The reference table (Markdown) written to docs/case-reference.md.
std::string reference_markdown();

}  // namespace cellsim
