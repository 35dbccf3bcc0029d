// catalog/sampler_prms.cpp: `gaussian-prm`, `obprm`, `bridge-prm` registered with their parameters;
// the distance they resolve (d, or d_scale x the robot's size) reaches the run's extras.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/prm/prm.hpp"
#include "amp/roadmap/run.hpp"
#include "roadmap/test_worlds.hpp"
#include "support/catalog_checks.hpp"

namespace amp::roadmap {
namespace {

PlannerRegistry sampler_prms_only() {
  PlannerRegistry r;
  register_sampler_prms(r);
  return r;
}

TEST(SamplerPrms, RegistersThreePlannersWithTheirParameters) {
  const PlannerRegistry r = sampler_prms_only();
  EXPECT_EQ(r.names(), (std::vector<std::string>{"bridge-prm", "gaussian-prm", "obprm"}));
  EXPECT_EQ(amp::test::param_names(r.info("gaussian-prm")),
            (std::vector<std::string>{"k", "d", "d_scale", "max_attempts"}));
  EXPECT_EQ(amp::test::param_names(r.info("obprm")), (std::vector<std::string>{"k", "max_attempts", "max_steps"}));
  EXPECT_EQ(amp::test::param_names(r.info("bridge-prm")),
            (std::vector<std::string>{"k", "d", "d_scale", "max_attempts", "uniform_mix"}));
  // UAS's distances: Gaussian d = r, bridge length 2r.
  EXPECT_EQ(amp::test::param_spec(r.info("gaussian-prm"), "d_scale").default_value, core::ParamValue(1.0));
  EXPECT_EQ(amp::test::param_spec(r.info("bridge-prm"), "d_scale").default_value, core::ParamValue(2.0));
  for (const char* name : {"gaussian-prm", "bridge-prm"}) {
    const core::ParamSpec& d = amp::test::param_spec(r.info(name), "d");
    EXPECT_EQ(d.default_value, core::ParamValue(0.0)) << name;  // 0 = auto
    const core::ParamSpec& scale = amp::test::param_spec(r.info(name), "d_scale");
    EXPECT_EQ(scale.min, 1e-6) << name;
    EXPECT_EQ(scale.max, 1e3) << name;
  }
  for (const char* name : {"gaussian-prm", "obprm", "bridge-prm"}) {
    // k is prm's own parameter, with prm's default and range.
    const core::ParamSpec& k = amp::test::param_spec(r.info(name), "k");
    EXPECT_EQ(k.default_value, core::ParamValue(10)) << name;
    EXPECT_EQ(k.max, 1000.0) << name;
    EXPECT_EQ(amp::test::param_spec(r.info(name), "max_attempts").default_value, core::ParamValue(100)) << name;
  }
  EXPECT_EQ(amp::test::param_spec(r.info("obprm"), "max_steps").default_value, core::ParamValue(1000));
  const core::ParamSpec& mix = amp::test::param_spec(r.info("bridge-prm"), "uniform_mix");
  EXPECT_EQ(mix.min, 0.0);
  EXPECT_EQ(mix.max, 1.0);
}

TEST(SamplerPrms, RangesAreEnforcedWithOneLineErrors) {
  const PlannerRegistry r = sampler_prms_only();
  for (const char* name : {"gaussian-prm", "obprm", "bridge-prm"}) amp::test::expect_declared_ranges_enforced(r, name);
}

TEST(SamplerPrms, MadePlannersArePrmsWithTheGivenK) {
  const PlannerRegistry r = sampler_prms_only();
  for (const char* name : {"gaussian-prm", "obprm", "bridge-prm"}) {
    const auto p = r.make(name, {{"k", 4}});
    EXPECT_EQ(dynamic_cast<const Prm&>(*p).settings().k, 4) << name;
  }
}

// A short run records the resolved sampler distance: d as given, or d_scale x (for the point robot,
// which has no size) 1% of the space's extent, sqrt(10^2 + 10^2).
TEST(SamplerPrms, RunsRecordTheResolvedSamplerDistance) {
  const PlannerRegistry r = sampler_prms_only();
  const world::Problem p = test::point_problem(true);
  const double extent = std::sqrt(200.0);
  for (const char* name : {"gaussian-prm", "bridge-prm"}) {
    SCOPED_TRACE(name);
    const RunOutcome given = execute_run(p, name, {{"d", 0.5}}, 1, 1e6, 30, r);
    EXPECT_DOUBLE_EQ(given.record.extra.at("sampler_d"), 0.5);
    EXPECT_EQ(given.record.extra.at("sampler_distance_fallback"), 0.0);
    const RunOutcome scaled = execute_run(p, name, {{"d_scale", 3.0}}, 1, 1e6, 30, r);
    EXPECT_DOUBLE_EQ(scaled.record.extra.at("sampler_d"), 3.0 * 0.01 * extent);
    EXPECT_EQ(scaled.record.extra.at("sampler_distance_fallback"), 1.0);
    EXPECT_TRUE(scaled.record.extra.contains("cc_create"));
  }
  const RunOutcome o = execute_run(p, "obprm", {}, 1, 1e6, 30, r);  // no distance to report
  EXPECT_FALSE(o.record.extra.contains("sampler_d"));
  EXPECT_TRUE(o.record.extra.contains("cc_create"));
}

}  // namespace
}  // namespace amp::roadmap
