#include "amp/core/parameters.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "amp/core/error.hpp"
#include "amp/core/number_text.hpp"

namespace amp::core {

namespace {

// The shortest text that reads back as v (0.3, not 0.29999999999999999).
// A whole string parsed as a number, or false.
bool parse_number(const std::string& s, double& out) {
  const char* first = s.data();
  const char* last = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(first, last, out);
  return ec == std::errc() && ptr == last && !s.empty();
}

bool parse_bool(const ParamValue& v, double& out) {
  if (v.is_number()) {
    out = v.number();
    return out == 0.0 || out == 1.0;
  }
  const std::string& s = v.string();
  if (s == "true" || s == "yes" || s == "on" || s == "1") {
    out = 1.0;
    return true;
  }
  if (s == "false" || s == "no" || s == "off" || s == "0") {
    out = 0.0;
    return true;
  }
  return false;
}

std::string join_names(const std::vector<ParamSpec>& specs) {
  std::string names;
  for (const ParamSpec& s : specs) names += (names.empty() ? "" : ", ") + s.name;
  return names.empty() ? "(none)" : names;
}

// Checks `v` against `spec`; returns the value in canonical form (numbers as numbers).
ParamValue check_value(const std::string& owner, const ParamSpec& spec, const ParamValue& v) {
  const std::string where = owner + ": parameter '" + spec.name + "'";
  switch (spec.type) {
    case ParamType::kBool: {
      double b = 0.0;
      if (!parse_bool(v, b)) throw ParameterError(where + ": expected true or false, got '" + v.to_string() + "'");
      return b;
    }
    case ParamType::kChoice: {
      const std::string s = v.to_string();
      for (const std::string& c : spec.choices) {
        if (c == s) return s;
      }
      std::string valid;
      for (const std::string& c : spec.choices) valid += (valid.empty() ? "" : ", ") + c;
      throw ParameterError(where + ": '" + s + "' is not one of " + valid);
    }
    case ParamType::kInteger:
    case ParamType::kReal: {
      double x = 0.0;
      if (v.is_number()) {
        x = v.number();
      } else if (!parse_number(v.string(), x)) {
        throw ParameterError(where + ": expected a number, got '" + v.string() + "'");
      }
      if (!std::isfinite(x)) throw ParameterError(where + ": expected a finite number, got " + v.to_string());
      if (spec.type == ParamType::kInteger && x != std::floor(x)) {
        throw ParameterError(where + ": expected an integer, got " + v.to_string());
      }
      if (x < spec.min || x > spec.max) {
        throw ParameterError(where + ": " + core::number_text(x) + " is outside [" + core::number_text(spec.min) + ", " +
                             core::number_text(spec.max) + "]");
      }
      return x;
    }
  }
  return v;
}

}  // namespace

std::string ParamValue::to_string() const { return is_number() ? core::number_text(number()) : string(); }

std::string_view to_string(ParamType t) {
  switch (t) {
    case ParamType::kInteger: return "integer";
    case ParamType::kReal: return "real";
    case ParamType::kBool: return "bool";
    case ParamType::kChoice: return "choice";
  }
  return "real";
}

Params::Params(const std::string& owner, const std::vector<ParamSpec>& specs, const ParamMap& given) {
  for (const auto& [name, value] : given) {
    bool known = false;
    for (const ParamSpec& s : specs) known = known || s.name == name;
    if (!known) {
      throw ParameterError(owner + ": unknown parameter '" + name + "' (valid: " + join_names(specs) + ")");
    }
  }
  for (const ParamSpec& s : specs) {
    const auto it = given.find(s.name);
    values_.insert_or_assign(s.name, check_value(owner, s, it == given.end() ? s.default_value : it->second));
  }
}

const ParamValue& Params::at(const std::string& name) const {
  const auto it = values_.find(name);
  // A factory asking for a parameter it did not declare is a programming error, not user input.
  if (it == values_.end()) throw std::logic_error("undeclared planner parameter '" + name + "'");
  return it->second;
}

long long Params::integer(const std::string& name) const { return static_cast<long long>(at(name).number()); }
double Params::real(const std::string& name) const { return at(name).number(); }
bool Params::boolean(const std::string& name) const { return at(name).number() != 0.0; }
const std::string& Params::choice(const std::string& name) const { return at(name).string(); }

}  // namespace amp::core
