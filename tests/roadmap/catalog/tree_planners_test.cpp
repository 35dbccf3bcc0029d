// catalog/tree_planners.cpp: `rrt-connect` registered with RrtConnectSettings' parameter.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/trees/rrt_connect.hpp"
#include "support/catalog_checks.hpp"

namespace amp::roadmap {
namespace {

PlannerRegistry trees_only() {
  PlannerRegistry r;
  register_rrt_connect(r);
  return r;
}

TEST(TreePlanners, RegistersRrtConnectWithItsRange) {
  const PlannerRegistry r = trees_only();
  EXPECT_EQ(r.names(), (std::vector<std::string>{"rrt-connect"}));
  const PlannerInfo& info = r.info("rrt-connect");
  EXPECT_EQ(amp::test::param_names(info), (std::vector<std::string>{"range"}));
  const core::ParamSpec& range = amp::test::param_spec(info, "range");
  EXPECT_EQ(range.type, core::ParamType::kReal);
  EXPECT_EQ(range.default_value, core::ParamValue(0.0));  // 0 = OMPL's default, 0.2 x the space's extent
  EXPECT_EQ(range.min, 0.0);
  EXPECT_EQ(range.max, 1e12);
}

TEST(TreePlanners, RangesAreEnforcedWithOneLineErrors) {
  amp::test::expect_declared_ranges_enforced(trees_only(), "rrt-connect");
}

TEST(TreePlanners, MadeRrtConnectCarriesTheGivenRange) {
  const auto p = trees_only().make("rrt-connect", {{"range", 2.5}});
  EXPECT_EQ(dynamic_cast<const RrtConnect&>(*p).settings().range, 2.5);
  const auto q = trees_only().make("rrt-connect", {});
  EXPECT_EQ(dynamic_cast<const RrtConnect&>(*q).settings().range, 0.0);
}

}  // namespace
}  // namespace amp::roadmap
