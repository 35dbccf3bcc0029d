// catalog/prm_planners.cpp: `prm` registered with PrmSettings' parameters.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/prm/prm.hpp"
#include "support/catalog_checks.hpp"

namespace amp::roadmap {
namespace {

PlannerRegistry prm_only() {
  PlannerRegistry r;
  register_prm(r);
  return r;
}

TEST(PrmPlanners, RegistersPrmWithItsParametersAndDefaults) {
  const PlannerRegistry r = prm_only();
  EXPECT_EQ(r.names(), (std::vector<std::string>{"prm"}));
  const PlannerInfo& info = r.info("prm");
  EXPECT_NE(info.help.find("Lazy PRM"), std::string::npos) << info.help;
  EXPECT_EQ(amp::test::param_names(info),
            (std::vector<std::string>{"k", "lazy", "smooth", "smooth_attempts", "skip_same_component"}));
  // The defaults are PrmSettings{}'s: k 10, smoothing off with 100 attempts, every neighbour tried.
  EXPECT_EQ(amp::test::param_spec(info, "k").default_value, core::ParamValue(10));
  EXPECT_EQ(amp::test::param_spec(info, "lazy").default_value, core::ParamValue(0));
  EXPECT_EQ(amp::test::param_spec(info, "smooth").default_value, core::ParamValue(0));
  EXPECT_EQ(amp::test::param_spec(info, "smooth_attempts").default_value, core::ParamValue(100));
  EXPECT_EQ(amp::test::param_spec(info, "skip_same_component").default_value, core::ParamValue(0));
  EXPECT_EQ(amp::test::param_spec(info, "k").max, 1000.0);
}

TEST(PrmPlanners, RangesAreEnforcedWithOneLineErrors) {
  amp::test::expect_declared_ranges_enforced(prm_only(), "prm");
}

TEST(PrmPlanners, MadePrmCarriesTheGivenValues) {
  const auto p = prm_only().make("prm", {{"k", 3}, {"smooth_attempts", 7}, {"skip_same_component", true}});
  const auto& s = dynamic_cast<const Prm&>(*p).settings();
  EXPECT_EQ(s.k, 3);
  EXPECT_EQ(s.smooth_attempts, 7);
  EXPECT_TRUE(s.skip_same_component);
  EXPECT_FALSE(s.lazy);
  EXPECT_FALSE(s.smooth);
}

}  // namespace
}  // namespace amp::roadmap
