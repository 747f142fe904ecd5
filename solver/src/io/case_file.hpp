#pragma once
// Reading a case: the JSON file, `--set key=value` overrides, validation against the schema.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/params.hpp"

namespace cellsim {

// Parses the file; throws InputError if it is missing, unreadable or not valid JSON.
nlohmann::json read_case_file(const std::string& path);

// Applies "section.key=value" (value as JSON: a number, true/false or null) to the document.
void apply_override(nlohmann::json& doc, const std::string& assignment);

// Checks every key, type and range; absent keys take their defaults. Throws InputError naming
// the key path, the value and what is allowed.
Params validate_case(const nlohmann::json& doc);

// The keys `doc` gives away from their defaults that the case's models will not read (the SPH-only keys
// of a closed-cell fluid, the relaxation's keys of a dynamic run), for a warning.
std::vector<std::string> keys_the_case_ignores(const nlohmann::json& doc, const Params& p);

// The case as JSON in the file's units, every key present (derived values filled in if known).
nlohmann::json case_to_json(const Params& p);

// Nearest valid key to a misspelt one (edit distance), for "did you mean" hints.
std::string nearest_key(const std::string& key, const std::vector<std::string>& candidates);

}  // namespace cellsim
