#include "io/case_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <cctype>
#include <set>
#include <sstream>

#include "core/errors.hpp"
#include "engine/density_update.hpp"
#include "engine/rotation_hold.hpp"
#include "engine/stage_caps.hpp"
#include "engine/steady_state.hpp"
#include "geometry/case_size.hpp"
#include "geometry/cell.hpp"
#include "io/case_schema.hpp"
#include "physics/volume_closure.hpp"

namespace cellsim {
namespace {

using nlohmann::json;

const char* kDescriptionKey = "description";  // free text allowed at the top level

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t subst = prev[j - 1] + (std::tolower(a[i - 1]) == std::tolower(b[j - 1]) ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::vector<std::string> all_keys() {
  std::vector<std::string> keys;
  for (const auto& s : param_specs()) keys.push_back(s.key);
  return keys;
}

std::set<std::string> sections() {
  std::set<std::string> out;
  for (const auto& s : param_specs()) out.insert(s.key.substr(0, s.key.find('.')));
  return out;
}

// True if v nests arrays or objects more than `limit` deep (a walk with its own stack: the serializer
// recurses, and a file of 100 000 brackets would overflow the call stack).
bool nested_deeper_than(const json& v, int limit) {
  std::vector<std::pair<const json*, int>> open{{&v, 0}};
  while (!open.empty()) {
    const auto [node, depth] = open.back();
    open.pop_back();
    if (!node->is_structured()) continue;
    if (depth >= limit) return true;
    for (const auto& child : *node) open.emplace_back(&child, depth + 1);
  }
  return false;
}

// A value as it appears in a message: bytes that are not UTF-8 (a --set of raw bytes) shown replaced,
// and a value nested deeper than any case shown by its kind only.
std::string show(const json& v) {
  if (nested_deeper_than(v, 8)) return v.is_array() ? "[[[...: an array nested over 8 deep" : "{{{...: an object nested over 8 deep";
  std::string s = v.dump(-1, ' ', false, json::error_handler_t::replace);
  return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}

[[noreturn]] void unknown_key(const std::string& path) {
  throw InputError("unknown key '" + path + "'; did you mean '" + nearest_key(path, all_keys()) +
                   "'? (run 'cellsim params' for the list of keys)");
}

bool within_range(const ParamSpec& spec, double x) {
  const bool above = spec.min_inclusive ? x >= spec.min : x > spec.min;
  const bool below = spec.max_inclusive ? x <= spec.max : x < spec.max;
  return above && below;
}

// Validates one leaf against its spec and stores it (in SI) into p.
void assign(const ParamSpec& spec, const json& value, Params& p) {
  const std::string where = spec.key + " = " + show(value);
  if (value.is_null()) {
    if (!is_optional(spec))
      throw InputError(where + ": a value is required (" + describe_range(spec) + ", in " + spec.unit + ")");
    std::visit(
        [&](auto member) {
          using M = decltype(member);
          if constexpr (std::is_same_v<M, std::optional<double> Params::*> ||
                        std::is_same_v<M, std::optional<std::int64_t> Params::*>)
            p.*member = std::nullopt;
        },
        spec.member);
    return;
  }
  if (is_choice(spec)) {
    const auto& names = spec.choices;
    const auto it = value.is_string() ? std::find(names.begin(), names.end(), value.get<std::string>()) : names.end();
    if (it == names.end()) throw InputError(where + ": expected " + describe_range(spec));
    p.*std::get<Choice Params::*>(spec.member) = static_cast<Choice>(it - names.begin());
    return;
  }
  if (!value.is_number())
    throw InputError(where + ": expected a number (" + describe_range(spec) + ", in " + spec.unit + ")" +
                     (is_optional(spec) ? " or null for auto" : ""));
  const double x = value.get<double>();
  if (!std::isfinite(x)) throw InputError(where + ": value must be finite (" + describe_range(spec) + ")");
  if (is_integer(spec) && x != std::floor(x))
    throw InputError(where + ": expected an integer (" + describe_range(spec) + ")");
  if (!within_range(spec, x))
    throw InputError(where + ": out of range; allowed " + describe_range(spec) + " (" + spec.unit + ")");
  if (x != 0 && !std::isnormal(x * spec.to_si))  // 5e-324 um passed "> 0" and became 0 m
    throw InputError(where + ": too small to hold in SI units (" + describe_range(spec) + ", in " + spec.unit + ")");
  std::visit(
      [&](auto member) {
        using M = decltype(member);
        if constexpr (std::is_same_v<M, std::int64_t Params::*> ||
                      std::is_same_v<M, std::optional<std::int64_t> Params::*>)
          p.*member = static_cast<std::int64_t>(x);
        else if constexpr (std::is_same_v<M, Choice Params::*>)
          p.*member = static_cast<Choice>(x);  // not reached: choices are names (above)
        else
          p.*member = x * spec.to_si;
      },
      spec.member);
}

}  // namespace

std::string nearest_key(const std::string& key, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const auto& c : candidates) {
    // Compare against the full path and its last part, so "G_Mpa" finds "wall.G_MPa".
    const std::size_t dot = c.rfind('.');
    const std::size_t d = std::min(edit_distance(key, c), dot == std::string::npos
                                                              ? edit_distance(key, c)
                                                              : edit_distance(key.substr(key.rfind('.') + 1),
                                                                              c.substr(dot + 1)));
    if (d < best_d) best_d = d, best = c;
  }
  return best;
}

// The first key given twice in one object, as "section.key" (nlohmann keeps the last and says
// nothing: the other value would be silently ignored); empty if none. A SAX pass over the text.
class DuplicateKeyFinder : public nlohmann::json_sax<json> {
 public:
  std::string duplicate;
  bool key(string_t& name) override {
    if (!open_.empty() && !open_.back().insert(name).second && duplicate.empty()) {
      for (const auto& outer : path_) duplicate += outer + ".";
      duplicate += name;
    }
    last_key_ = name;
    return true;
  }
  bool start_object(std::size_t) override {
    if (!open_.empty()) path_.push_back(last_key_);
    open_.emplace_back();
    return true;
  }
  bool end_object() override {
    open_.pop_back();
    if (!path_.empty()) path_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    open_.emplace_back();  // an array's objects are not the case's keys: their own scopes
    path_.push_back(last_key_ + "[]");
    return true;
  }
  bool end_array() override { return end_object(); }
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  std::vector<std::set<std::string>> open_;
  std::vector<std::string> path_;
  std::string last_key_;
};

// The JSON parser rejects numbers like 1e999 without saying where; find the key they belong to: the
// last string before the token that a colon follows, and the last such string a '{' follows (its
// section). One pass over the text (std::regex recursed per character and overflowed the stack on a
// 100 000-character string: found by the fuzzer, issue 51).
std::string key_before(const std::string& text, const std::string& token) {
  const auto at = text.find(token);
  if (at == std::string::npos) return "?";
  std::string key, section;
  const auto skip_space = [&](std::size_t i) {
    while (i < at && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    return i;
  };
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] != '"') continue;
    std::size_t end = i + 1;  // the closing quote, past escaped characters
    while (end < at && text[end] != '"') end += text[end] == '\\' ? 2 : 1;
    if (end >= at) break;
    const std::string name = text.substr(i + 1, end - i - 1);
    const std::size_t colon = skip_space(end + 1);
    if (colon < at && text[colon] == ':') {
      key = name;
      const std::size_t value = skip_space(colon + 1);
      if (value < at && text[value] == '{') section = name;
    }
    i = end;
  }
  return section.empty() || section == key ? key : section + "." + key;
}

json read_case_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot open case file '" + path + "': no such file or not readable");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The JSON library reads a NUL byte as the end of its input: whatever followed would be ignored.
  if (const auto nul = text.find('\0'); nul != std::string::npos)
    throw InputError("case file '" + path + "' is not valid JSON: a NUL byte at offset " + std::to_string(nul) +
                     " (a JSON text holds none; the file may be truncated or binary)");
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError("case file '" + path + "' is not valid JSON: " + e.what());
  } catch (const json::out_of_range& e) {  // number overflow, e.g. 1e999
    const std::string what = e.what();
    const auto q1 = what.find('\''), q2 = what.rfind('\'');
    const std::string token = q1 != std::string::npos && q2 > q1 ? what.substr(q1 + 1, q2 - q1 - 1) : "";
    throw InputError(key_before(text, token) + " = " + token + ": value must be finite (case file '" + path + "')");
  }
  if (!doc.is_object())
    throw InputError("case file '" + path + "' holds " + show(doc) + ": a case is a JSON object of sections " +
                     show(json(sections())));
  DuplicateKeyFinder finder;
  json::sax_parse(text, &finder);
  if (!finder.duplicate.empty())
    throw InputError(finder.duplicate + " is given twice in case file '" + path + "' (one of the values would be "
                     "ignored): keep one");
  return doc;
}

void apply_override(json& doc, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set '" + assignment + "': expected section.key=value, e.g. drying.dryness=0.5");
  const std::string key = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  if (!find_param(key)) unknown_key(key);
  const std::string section = key.substr(0, key.find('.'));
  if (!doc.is_object()) doc = json::object();
  if (!doc.contains(section) || !doc[section].is_object()) doc[section] = json::object();
  if (is_choice(*find_param(key))) {  // a name, as typed (--set coupling.model=pressure) or as JSON ("pressure")
    const bool quoted = text.size() >= 2 && text.front() == '"' && text.back() == '"';
    doc[section][key.substr(key.find('.') + 1)] = quoted ? text.substr(1, text.size() - 2) : text;
    return;
  }
  std::string lower = text;
  std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
  if (lower == "nan" || lower == "inf" || lower == "-inf" || lower == "infinity" || lower == "-infinity")
    throw InputError(key + " = " + text + ": value must be finite (" + describe_range(*find_param(key)) + ")");
  json value;
  try {
    value = json::parse(text);
  } catch (const json::out_of_range&) {  // a number too large for a double, e.g. 1e400
    throw InputError(key + " = " + text + ": value must be finite (" + describe_range(*find_param(key)) + ")");
  } catch (const json::exception&) {
    throw InputError(key + " = '" + text + "': not a number (" + describe_range(*find_param(key)) + ")");
  }
  doc[section][key.substr(key.find('.') + 1)] = value;
}

namespace {

// Whether the case file gives `key` a value other than its default (a derived key: any value).
bool given_away_from_default(const json& doc, const std::string& key) {
  const std::size_t dot = key.find('.');
  const std::string section = key.substr(0, dot), name = key.substr(dot + 1);
  if (!doc.contains(section) || !doc[section].is_object() || !doc[section].contains(name)) return false;
  const json& value = doc[section][name];
  const ParamSpec& spec = *find_param(key);
  if (is_choice(spec)) return value != json(spec.choices.front());
  if (!spec.default_value) return !value.is_null();
  return !value.is_number() || value.get<double>() != *spec.default_value;
}

}  // namespace

std::vector<std::string> keys_the_case_ignores(const json& doc, const Params& p) {
  std::vector<std::string> ignored;
  // A key whose value is the one the case takes without it (as `cellsim validate` prints a resolved
  // case: compression.cell_rotation = free for a dynamic cell) asks for nothing the case does not do.
  const json resolved = case_to_json(p);
  const auto as_without = [&](const std::string& key) {
    const std::size_t dot = key.find('.');
    const std::string section = key.substr(0, dot), name = key.substr(dot + 1);
    json without = doc;
    without[section].erase(name);
    try {
      return case_to_json(validate_case(without))[section][name] == resolved[section][name];
    } catch (const InputError&) {
      return false;  // the case needs the key's value: it is given, and warned as ignored
    }
  };
  const auto add = [&](const std::vector<std::string>& keys) {
    for (const auto& key : keys)
      if (given_away_from_default(doc, key) && !as_without(key)) ignored.push_back(key);
  };
  for (const KeysReadOnlyBy& own : keys_read_only_by()) {  // a reader's keys, where the case is another's
    const std::size_t dot = own.choice_key.find('.');
    if (resolved[own.choice_key.substr(0, dot)][own.choice_key.substr(dot + 1)] != own.value) add(own.keys);
  }
  return ignored;
}

Params validate_case(const json& doc) {
  if (!doc.is_object()) throw InputError("case must be a JSON object with sections " + show(json(sections())));
  Params p;
  for (const auto& spec : param_specs())  // defaults first; derived keys start empty
    if (is_choice(spec))
      assign(spec, spec.choices.front(), p);
    else if (spec.default_value)
      assign(spec, *spec.default_value, p);

  const auto known_sections = sections();
  for (const auto& [section, body] : doc.items()) {
    if (section == kDescriptionKey) {
      if (!body.is_string()) throw InputError("description = " + show(body) + ": expected a string");
      continue;
    }
    if (!known_sections.count(section)) {
      if (body.is_object() && !body.empty()) unknown_key(section + "." + body.begin().key());
      unknown_key(section);
    }
    if (!body.is_object())
      throw InputError(section + " = " + show(body) + ": expected an object of " + section + ".* keys");
    for (const auto& [name, value] : body.items()) {
      const std::string path = section + "." + name;
      const ParamSpec* spec = find_param(path);
      if (!spec) unknown_key(path);
      assign(*spec, value, p);
    }
  }
  if (p.time_scheme == kQuasiStatic && p.fluid_model != kCavityFluid)
    throw InputError("time.scheme = quasi_static needs fluid.model = cavity: an SPH fluid has no equilibrium of its "
                     "own to relax to (its pressure is its particles' motion)");
  check_case_size(p);
  resolve_steady_state_defaults(p);
  resolve_density_update(p);
  resolve_cell_rotation(p);
  resolve_unloading(p);
  resolve_stage_caps(p);
  resolve_volume_closure(p);
  resolve_derived_geometry(p);  // r0, the fill gap, h0 and h0/dx, the wall gap: from the paper's cell (cell.hpp)
  // An h0 in um makes an h0/dx of this cell's lattice, which the case as validate prints it gives too: it
  // must lie in that key's range (h0 = 0.5 um on a 21 um lattice left the fluid no neighbours).
  const ParamSpec& ratio = *find_param("fluid.h_over_dx");
  if (!within_range(ratio, *p.h_over_dx)) {
    std::ostringstream msg;
    msg << "fluid.h0_um = " << *p.h0_m * 1e6 << " gives h0/dx = " << *p.h_over_dx << " on this cell's fluid lattice (dx = "
        << *p.h0_m / *p.h_over_dx * 1e6 << " um): outside fluid.h_over_dx's range " << describe_range(ratio);
    throw InputError(msg.str());
  }
  return p;
}

// SI back to the file's unit, rounded to 15 significant digits so 150e-6 / 1e-6 prints as 150.
double to_file_unit(double si, double to_si) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", si / to_si);
  return std::strtod(text, nullptr);
}

json case_to_json(const Params& p) {
  json doc = json::object();
  for (const auto& spec : param_specs()) {
    const std::string section = spec.key.substr(0, spec.key.find('.'));
    const std::string name = spec.key.substr(spec.key.find('.') + 1);
    json value;
    std::visit(
        [&](auto member) {
          using M = decltype(member);
          if constexpr (std::is_same_v<M, std::int64_t Params::*>)
            value = p.*member;
          else if constexpr (std::is_same_v<M, std::optional<std::int64_t> Params::*>)
            value = (p.*member) ? json(*(p.*member)) : json(nullptr);
          else if constexpr (std::is_same_v<M, Choice Params::*>)
            value = spec.choices.at(static_cast<std::size_t>(p.*member));
          else if constexpr (std::is_same_v<M, double Params::*>)
            value = to_file_unit(p.*member, spec.to_si);
          else
            value = (p.*member) ? json(to_file_unit(*(p.*member), spec.to_si)) : json(nullptr);
        },
        spec.member);
    doc[section][name] = value;
  }
  return doc;
}

}  // namespace cellsim
