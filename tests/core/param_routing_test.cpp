#include "amp/core/param_routing.hpp"

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/number_text.hpp"

namespace amp::core {
namespace {

std::vector<ParamSpec> specs(std::initializer_list<const char*> names) {
  std::vector<ParamSpec> out;
  for (const char* n : names) out.push_back(ParamSpec{n, ParamType::kReal, 0.0, 0.0, 1.0, {}, ""});
  return out;
}

TEST(RouteParams, EachParameterGoesToEverySchemaThatDeclaresIt) {
  const auto a = specs({"worlds", "clutter"}), b = specs({"max_cases", "case_length"}), c = specs({"max_cases", "step"});
  const ParamMap given = {{"clutter", ParamValue(0.3)}, {"max_cases", ParamValue(7.0)}, {"step", ParamValue(0.1)}};
  const std::vector<ParamMap> routed = route_params(given, {&a, &b, &c});
  ASSERT_EQ(routed.size(), 3u);
  EXPECT_EQ(routed[0].size(), 1u);
  EXPECT_EQ(routed[0].at("clutter").number(), 0.3);
  EXPECT_EQ(routed[1].size(), 1u);
  EXPECT_EQ(routed[1].at("max_cases").number(), 7.0);
  EXPECT_EQ(routed[2].size(), 2u);
  EXPECT_TRUE(routed[2].contains("max_cases") && routed[2].contains("step"));
  EXPECT_TRUE(route_params({}, {&a, &b})[0].empty());
}

TEST(RouteParams, AnUnknownNameListsTheValidOnesOnceInOrder) {
  const auto a = specs({"worlds", "clutter"}), b = specs({"max_cases"}), c = specs({"max_cases", "step"});
  try {
    route_params({{"nope", ParamValue(1.0)}}, {&a, &b, &c});
    FAIL() << "expected ParameterError";
  } catch (const ParameterError& e) {
    EXPECT_STREQ(e.what(), "unknown parameter 'nope' (valid: worlds, clutter, max_cases, step)");
  }
}

TEST(NumberText, TheShortestTextThatReadsBack) {
  EXPECT_EQ(number_text(0.1), "0.1");
  EXPECT_EQ(number_text(3.0), "3");
  EXPECT_EQ(number_text(1e-7), "1e-07");
  EXPECT_EQ(number_text(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(std::stod(number_text(2.0 / 3.0)), 2.0 / 3.0);
  EXPECT_EQ(number_text(-2.5), "-2.5");
}

}  // namespace
}  // namespace amp::core
