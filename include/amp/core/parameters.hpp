#pragma once
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace amp::core {

// A planner parameter as the user wrote it: a number, or a string (a word, or a number or boolean
// not yet parsed, as it comes from the command line).
class ParamValue {
 public:
  // Implicit, so that a ParamMap reads naturally: {{"k", 15}, {"lazy", true}}. Booleans are 0 / 1.
  template <class T>
    requires std::is_arithmetic_v<T>
  ParamValue(T v) : value_(static_cast<double>(v)) {}   // NOLINT
  ParamValue(std::string v) : value_(std::move(v)) {}    // NOLINT
  ParamValue(const char* v) : value_(std::string(v)) {}  // NOLINT

  bool is_number() const { return std::holds_alternative<double>(value_); }
  double number() const { return std::get<double>(value_); }
  const std::string& string() const { return std::get<std::string>(value_); }
  // The value as text, for messages and records.
  std::string to_string() const;

  friend bool operator==(const ParamValue&, const ParamValue&) = default;

 private:
  std::variant<double, std::string> value_;
};

using ParamMap = std::map<std::string, ParamValue>;

enum class ParamType { kInteger, kReal, kBool, kChoice };
std::string_view to_string(ParamType t);

// One parameter a planner accepts, as `amp bench --list` prints it.
struct ParamSpec {
  std::string name;
  ParamType type = ParamType::kReal;
  ParamValue default_value = 0.0;
  double min = 0.0;  // inclusive range for kInteger and kReal
  double max = 0.0;
  std::vector<std::string> choices;  // for kChoice
  std::string help;
};

// A planner's parameters after checking: every declared parameter present with the right type and
// within range (defaults filled in). Factories read them typed.
class Params {
 public:
  // Throws ParameterError for an unknown name (listing the valid ones), a wrong type or an
  // out-of-range value; `owner` (the planner name) prefixes every message.
  Params(const std::string& owner, const std::vector<ParamSpec>& specs, const ParamMap& given);

  long long integer(const std::string& name) const;
  double real(const std::string& name) const;
  bool boolean(const std::string& name) const;
  const std::string& choice(const std::string& name) const;
  // Resolved values by name (numbers and booleans as numbers), for records.
  const ParamMap& values() const { return values_; }

 private:
  const ParamValue& at(const std::string& name) const;
  ParamMap values_;
};

}  // namespace amp::core
