// catalog/competence_planners.cpp: `prm-c`, `prm-g`, `prm-l`, one per form of the competence
// threshold, each with its own parameter (o, s, n) before the shared CompetencePrmSettings ones.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/run.hpp"
#include "roadmap/test_worlds.hpp"
#include "support/catalog_checks.hpp"

namespace amp::roadmap {
namespace {

PlannerRegistry competence_only() {
  PlannerRegistry r;
  register_competence_prms(r);
  return r;
}

struct Form {
  const char* planner;
  const char* parameter;
  double fallback, lo, hi;
};
constexpr Form kForms[] = {{"prm-c", "o", 8, 1, 1e6}, {"prm-g", "s", 1000, 1, 1e9}, {"prm-l", "n", 0.1, 0.001, 1000}};

TEST(CompetencePlanners, RegistersOnePlannerPerFormWithItsOwnParameterFirst) {
  const PlannerRegistry r = competence_only();
  EXPECT_EQ(r.names(), (std::vector<std::string>{"prm-c", "prm-g", "prm-l"}));
  for (const Form& f : kForms) {
    SCOPED_TRACE(f.planner);
    const PlannerInfo& info = r.info(f.planner);
    EXPECT_EQ(amp::test::param_names(info),
              (std::vector<std::string>{f.parameter, "k", "steps", "a", "b", "max_cells"}));
    const core::ParamSpec& own = info.params.front();
    EXPECT_EQ(own.type, core::ParamType::kReal);
    EXPECT_EQ(own.default_value, core::ParamValue(f.fallback));
    EXPECT_EQ(own.min, f.lo);
    EXPECT_EQ(own.max, f.hi);
    EXPECT_NE(info.help.find("Isto 2003"), std::string::npos) << info.help;
    // The grid's defaults (GridAStarSettings{}): 128 steps, f = 3 g + 5 h.
    EXPECT_EQ(amp::test::param_spec(info, "steps").default_value, core::ParamValue(128));
    EXPECT_EQ(amp::test::param_spec(info, "a").default_value, core::ParamValue(3));
    EXPECT_EQ(amp::test::param_spec(info, "b").default_value, core::ParamValue(5));
  }
}

TEST(CompetencePlanners, RangesAreEnforcedWithOneLineErrors) {
  const PlannerRegistry r = competence_only();
  for (const Form& f : kForms) amp::test::expect_declared_ranges_enforced(r, f.planner);
}

// The form's value reaches the run: each planner records its own parameter, as given or by default.
TEST(CompetencePlanners, RunsRecordTheirFormsValue) {
  const PlannerRegistry r = competence_only();
  const world::Problem p = test::point_problem(true);
  const double given[] = {4, 300, 0.3};
  for (std::size_t i = 0; i < 3; ++i) {
    const Form& f = kForms[i];
    SCOPED_TRACE(f.planner);
    const RunOutcome a = execute_run(p, f.planner, {{f.parameter, given[i]}}, 1, 1e6, 20, r);
    EXPECT_EQ(a.record.extra.at(f.parameter), given[i]);
    const RunOutcome b = execute_run(p, f.planner, {}, 1, 1e6, 20, r);
    EXPECT_EQ(b.record.extra.at(f.parameter), f.fallback);
    for (const Form& other : kForms) {
      if (&other != &f) {
        EXPECT_FALSE(a.record.extra.contains(other.parameter)) << other.parameter;
      }
    }
  }
}

TEST(CompetencePrm, BadParametersAreRejected) {
  const auto& reg = builtin_planners();
  EXPECT_THROW(reg.make("prm-c", {{"o", 0.5}}), ParameterError);
  EXPECT_THROW(reg.make("prm-g", {{"s", 0}}), ParameterError);
  EXPECT_THROW(reg.make("prm-l", {{"n", -1}}), ParameterError);
  EXPECT_THROW(reg.make("prm-l", {{"steps", 0}}), ParameterError);
  EXPECT_THROW(reg.make("prm-c", {{"n", 4}}), ParameterError);  // PRM-C has o, not n
  for (const char* name : {"prm-c", "prm-g", "prm-l"}) {
    EXPECT_NE(reg.make(name, {}), nullptr) << name;
  }
}

}  // namespace
}  // namespace amp::roadmap
