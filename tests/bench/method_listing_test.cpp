// method_listing.cpp: `amp bench --list` shows planners and navigation methods in sections of their own.
#include "amp/bench/method_listing.hpp"

#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "amp/nav/navigator_catalog.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"

namespace amp::bench {
namespace {

TEST(MethodListing, PlannersThenNavigationMethodsEachInItsSection) {
  std::ostringstream out;
  list_methods(out);
  const std::string text = out.str();
  const auto planners = text.find("Planners:\n");
  const auto navigators = text.find("\nNavigation methods:\n");
  ASSERT_NE(planners, std::string::npos) << text;
  ASSERT_NE(navigators, std::string::npos) << text;
  EXPECT_LT(planners, navigators);
  for (const std::string& name : roadmap::builtin_planners().names()) {
    const auto at = text.find("\n  " + name + "  ");
    EXPECT_TRUE(at != std::string::npos && at < navigators) << name << " under Planners";
  }
  const auto& catalog = nav::builtin_navigators();
  for (const std::string& name : catalog.names()) {
    EXPECT_NE(text.find("\n  " + name + "  ", navigators), std::string::npos) << name << " under Navigation methods";
  }
  if (catalog.names().empty()) {
    EXPECT_NE(text.find("(none registered)", navigators), std::string::npos);
  }
  // Parameters are listed under their method with type and default, as before.
  EXPECT_NE(text.find("      k (integer, default "), std::string::npos) << text.substr(0, 600);
}

}  // namespace
}  // namespace amp::bench
