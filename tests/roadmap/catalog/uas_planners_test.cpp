// catalog/uas_planners.cpp: `hybrid-prm` and `uas` registered with their settings' parameters.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/prm/prm.hpp"
#include "support/catalog_checks.hpp"

namespace amp::roadmap {
namespace {

PlannerRegistry uas_only() {
  PlannerRegistry r;
  register_uas_planners(r);
  return r;
}

TEST(UasPlanners, RegistersHybridPrmAndUasWithTheirParameters) {
  const PlannerRegistry r = uas_only();
  EXPECT_EQ(r.names(), (std::vector<std::string>{"hybrid-prm", "uas"}));
  EXPECT_EQ(amp::test::param_names(r.info("hybrid-prm")),
            (std::vector<std::string>{"gamma", "alpha", "cost", "k", "bridge", "expansion", "sequence"}));
  EXPECT_EQ(amp::test::param_names(r.info("uas")),
            (std::vector<std::string>{"clustering", "training_nodes", "training_k", "training_visibility",
                                      "region_margin", "m", "schedule", "k", "gamma", "alpha", "cost", "bridge",
                                      "expansion", "reuse_training", "whole_space_region", "sequence"}));
  for (const char* name : {"hybrid-prm", "uas"}) {
    const PlannerInfo& info = r.info(name);
    // UAS's figures: gamma 0.5 (chance and past performance weigh alike), alpha 4, cost per node.
    EXPECT_EQ(amp::test::param_spec(info, "gamma").default_value, core::ParamValue(0.5)) << name;
    EXPECT_EQ(amp::test::param_spec(info, "alpha").default_value, core::ParamValue(4.0)) << name;
    EXPECT_EQ(amp::test::param_spec(info, "cost").default_value, core::ParamValue("node")) << name;
    EXPECT_EQ(amp::test::param_spec(info, "sequence").choices, (std::vector<std::string>{"random", "halton"})) << name;
  }
  const PlannerInfo& uas = r.info("uas");
  EXPECT_EQ(amp::test::param_spec(uas, "training_nodes").default_value, core::ParamValue(200));
  EXPECT_EQ(amp::test::param_spec(uas, "training_nodes").min, 2.0);
  EXPECT_EQ(amp::test::param_spec(uas, "training_k").default_value, core::ParamValue(5));
  EXPECT_EQ(amp::test::param_spec(uas, "clustering").default_value, core::ParamValue("kmeans"));
  EXPECT_EQ(amp::test::param_spec(uas, "clustering").choices,
            (std::vector<std::string>{"kmeans", "ward", "pgmeans", "auto"}));
  EXPECT_EQ(amp::test::param_spec(uas, "region_margin").default_value, core::ParamValue(0.0));
  EXPECT_EQ(amp::test::param_spec(uas, "schedule").choices,
            (std::vector<std::string>{"weighted", "round-robin", "adaptive"}));
}

TEST(UasPlanners, RangesAreEnforcedWithOneLineErrors) {
  const PlannerRegistry r = uas_only();
  for (const char* name : {"hybrid-prm", "uas"}) amp::test::expect_declared_ranges_enforced(r, name);
}

TEST(UasPlanners, HybridPrmIsAPrmWithTheGivenK) {
  const auto p = uas_only().make("hybrid-prm", {{"k", 6}, {"bridge", true}});
  EXPECT_EQ(dynamic_cast<const Prm&>(*p).settings().k, 6);
}

// The built-in registry refuses bad Hybrid PRM and sampler-PRM values.
TEST(HybridPrm, RegisteredWithItsParameters) {
  const PlannerRegistry& r = builtin_planners();
  for (const char* name : {"hybrid-prm", "gaussian-prm", "obprm", "bridge-prm"}) EXPECT_TRUE(r.contains(name)) << name;
  EXPECT_THROW(r.make("hybrid-prm", {{"gamma", 0.0}}), ParameterError);
  EXPECT_THROW(r.make("hybrid-prm", {{"alpha", -1.0}}), ParameterError);
  EXPECT_THROW(r.make("gaussian-prm", {{"d", -1.0}}), ParameterError);
  EXPECT_THROW(r.make("bridge-prm", {{"uniform_mix", 2.0}}), ParameterError);
  EXPECT_NO_THROW(r.make("gaussian-prm", {{"d_scale", 2.0}}));
}

TEST(Uas, RejectsBadParameters) {
  const PlannerRegistry& r = builtin_planners();
  ASSERT_TRUE(r.contains("uas"));
  EXPECT_THROW(r.make("uas", {{"clustering", "dbscan"}}), ParameterError);
  EXPECT_THROW(r.make("uas", {{"m", 0}}), ParameterError);
  EXPECT_THROW(r.make("uas", {{"training_nodes", 1}}), ParameterError);
  EXPECT_THROW(r.make("uas", {{"region_margin", -1}}), ParameterError);
  EXPECT_THROW(r.make("uas", {{"schedule", "random"}}), ParameterError);
  EXPECT_NO_THROW(r.make("uas", {{"schedule", "round-robin"}}));
  EXPECT_NO_THROW(r.make("uas", {{"clustering", "auto"}, {"schedule", "adaptive"}, {"reuse_training", false}}));
}

}  // namespace
}  // namespace amp::roadmap
