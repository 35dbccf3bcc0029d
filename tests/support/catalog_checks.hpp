#pragma once
// Shared by the catalog tests (tests/roadmap/catalog): a registered planner declares the parameters
// its catalog file names, with defaults inside their ranges; it is made at both ends of every range
// and with every choice, and a value outside is refused with a one-line ParameterError that names the
// planner and the parameter.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"

namespace amp::test {

inline std::vector<std::string> param_names(const roadmap::PlannerInfo& info) {
  std::vector<std::string> names;
  for (const core::ParamSpec& s : info.params) names.push_back(s.name);
  return names;
}

inline const core::ParamSpec& param_spec(const roadmap::PlannerInfo& info, const std::string& name) {
  for (const core::ParamSpec& s : info.params) {
    if (s.name == name) return s;
  }
  throw std::logic_error("no parameter '" + name + "' in " + info.name);
}

// The message of the ParameterError `f` throws ("" if none).
template <class F>
std::string parameter_error(F&& f) {
  try {
    f();
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

// `planner` with the one parameter `name` = `value` is refused with a one-line message
// "<planner>: parameter '<name>': ..." that contains `part`.
inline void expect_refused(const roadmap::PlannerRegistry& r, const std::string& planner, const std::string& name,
                           const core::ParamValue& value, const std::string& part) {
  const std::string m = parameter_error([&] { r.make(planner, {{name, value}}); });
  ASSERT_FALSE(m.empty()) << planner << " accepted " << name << " = " << value.to_string();
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  EXPECT_EQ(m.rfind(planner + ": parameter '" + name + "'", 0), 0u) << m;
  EXPECT_NE(m.find(part), std::string::npos) << m;
}

// Every declared parameter of `planner`: the default lies in the range, both ends of the range (each
// choice, both booleans) are accepted, and values just outside are refused.
inline void expect_declared_ranges_enforced(const roadmap::PlannerRegistry& r, const std::string& planner) {
  for (const core::ParamSpec& s : r.info(planner).params) {
    SCOPED_TRACE(planner + ": " + s.name);
    EXPECT_FALSE(s.help.empty());
    switch (s.type) {
      case core::ParamType::kInteger:
      case core::ParamType::kReal:
        ASSERT_TRUE(s.default_value.is_number());
        EXPECT_GE(s.default_value.number(), s.min);
        EXPECT_LE(s.default_value.number(), s.max);
        EXPECT_NO_THROW(r.make(planner, {{s.name, s.min}}));
        EXPECT_NO_THROW(r.make(planner, {{s.name, s.max}}));
        expect_refused(r, planner, s.name, s.min - 1.0, "is outside [");
        expect_refused(r, planner, s.name, s.max + 1.0, "is outside [");
        expect_refused(r, planner, s.name, "many", "expected a number");
        if (s.type == core::ParamType::kInteger) expect_refused(r, planner, s.name, s.min + 0.5, "expected an integer");
        break;
      case core::ParamType::kBool:
        EXPECT_NO_THROW(r.make(planner, {{s.name, true}}));
        EXPECT_NO_THROW(r.make(planner, {{s.name, "false"}}));
        expect_refused(r, planner, s.name, "maybe", "true or false");
        break;
      case core::ParamType::kChoice:
        ASSERT_FALSE(s.choices.empty());
        EXPECT_NE(std::find(s.choices.begin(), s.choices.end(), s.default_value.to_string()), s.choices.end());
        for (const std::string& c : s.choices) EXPECT_NO_THROW(r.make(planner, {{s.name, c}})) << c;
        expect_refused(r, planner, s.name, "no-such-choice", "is not one of");
        break;
    }
  }
  {  // and a name it does not declare
    const std::string m = parameter_error([&] { r.make(planner, {{"no_such_parameter", 1}}); });
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_NE(m.find("unknown parameter 'no_such_parameter'"), std::string::npos) << m;
  }
}

}  // namespace amp::test
