// competence/competence_policy.cpp: the competence threshold O_th of PRM-C, PRM-G and PRM-L.
#include "amp/roadmap/competence/competence_policy.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"

namespace amp::roadmap {
namespace {

TEST(CompetencePolicy, StaticIsFixed) {
  StaticCompetence c(8);
  EXPECT_EQ(c.threshold(EdgeRequest{1, 2, 50}), 8.0);
  EXPECT_THROW(StaticCompetence(0.5), ParameterError);
}

TEST(CompetencePolicy, GlobalGrowsWithTheRoadmap) {
  GlobalCompetence g(1000);
  EXPECT_DOUBLE_EQ(g.threshold(EdgeRequest{1, 2, 100}), 3.2);   // 100 / 1000 * 32
  EXPECT_DOUBLE_EQ(g.threshold(EdgeRequest{1, 2, 2000}), 64.0);
  EXPECT_DOUBLE_EQ(g.threshold(EdgeRequest{}), 64.0);  // no size given: the last one
  EXPECT_THROW(GlobalCompetence(0), ParameterError);
}

TEST(CompetencePolicy, LocalFollowsEachVertexsFailures) {
  LocalCompetence l(0.3);
  EXPECT_DOUBLE_EQ(l.threshold(EdgeRequest{7, 3, 10}), 1.3);  // untried: r_s = 1
  // Vertex 3: one success, three failures -> r_s = (1 + 1) / (4 + 1) = 0.4, O_th = 1 + 0.3 / 0.4.
  l.record(EdgeRequest{4, 3, 10}, true);
  for (std::size_t v : {5u, 6u, 8u}) l.record(EdgeRequest{v, 3, 10}, false);
  EXPECT_DOUBLE_EQ(l.success_ratio(3), 0.4);
  EXPECT_DOUBLE_EQ(l.success_ratio(5), 0.5);  // (0 + 1) / (1 + 1)
  EXPECT_DOUBLE_EQ(l.threshold(EdgeRequest{9, 3, 10}), 1.75);  // the larger of the two ends
  EXPECT_DOUBLE_EQ(l.threshold(EdgeRequest{3, 9, 10}), 1.75);
  EXPECT_DOUBLE_EQ(l.threshold(EdgeRequest{4, 9, 10}), 1.3);  // 4: (1 + 1) / (1 + 1) = 1
  EXPECT_THROW(LocalCompetence(0), ParameterError);
}

// Decisions on hand cases: which edges each policy lets a search of competence O = 2.5 attempt
// (O <= O_th), and how the thresholds move as the roadmap grows or edges fail.
TEST(CompetencePolicy, HandCasesOfWhichSearchesAreAllowed) {
  constexpr double kSearch = 2.5;
  StaticCompetence c(2);
  EXPECT_FALSE(kSearch <= c.threshold(EdgeRequest{0, 1, 10}));
  EXPECT_FALSE(kSearch <= c.threshold(EdgeRequest{0, 1, 100000}));  // PRM-C never changes its mind
  c.record(EdgeRequest{0, 1, 10}, false);
  EXPECT_EQ(c.threshold(EdgeRequest{0, 1, 10}), 2.0);

  // PRM-G, s = 300: O_th = S / 300 * 32, so O = 2.5 is allowed from S = 2.5 * 300 / 32 = 23.4375.
  GlobalCompetence g(300);
  EXPECT_FALSE(kSearch <= g.threshold(EdgeRequest{0, 1, 23}));  // 2.4533...
  EXPECT_TRUE(kSearch <= g.threshold(EdgeRequest{0, 1, 24}));   // 2.56
  EXPECT_DOUBLE_EQ(g.threshold(EdgeRequest{0, 1, 24}), 2.56);
  // Before any size: a tiny positive threshold that refuses every search (O >= 1).
  GlobalCompetence fresh(300);
  const double none = fresh.threshold(EdgeRequest{});
  EXPECT_GT(none, 0.0);
  EXPECT_LT(none, 1.0);

  // PRM-L, n = 1: O_th(v) = 1 + 1 / r_s(v). Two failures at vertex 0: r_s = 1 / 3, O_th = 4: the
  // harder search is allowed next to a vertex that keeps failing; two successes at 1: r_s = 1, O_th = 2.
  LocalCompetence l(1.0);
  EXPECT_DOUBLE_EQ(l.threshold(EdgeRequest{0, 1, 5}), 2.0);
  EXPECT_FALSE(kSearch <= l.threshold(EdgeRequest{0, 1, 5}));
  l.record(EdgeRequest{0, EdgeRequest::kNoVertex, 5}, false);  // an end without a vertex is not counted
  l.record(EdgeRequest{EdgeRequest::kNoVertex, 0, 5}, false);
  l.record(EdgeRequest{1, 2, 5}, true);
  l.record(EdgeRequest{2, 1, 5}, true);
  EXPECT_DOUBLE_EQ(l.success_ratio(0), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(l.success_ratio(1), 1.0);
  EXPECT_DOUBLE_EQ(l.success_ratio(2), 1.0);
  EXPECT_DOUBLE_EQ(l.threshold(EdgeRequest{0, 1, 5}), 4.0);
  EXPECT_TRUE(kSearch <= l.threshold(EdgeRequest{1, 0, 5}));
  EXPECT_FALSE(kSearch <= l.threshold(EdgeRequest{1, 2, 5}));
  // A vertex never seen (beyond every count) has r_s = 1.
  EXPECT_DOUBLE_EQ(l.success_ratio(1000), 1.0);
}

TEST(CompetencePolicy, RefusesNonFiniteValues) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(StaticCompetence{inf}, ParameterError);
  EXPECT_THROW(StaticCompetence{std::nan("")}, ParameterError);
  EXPECT_THROW(GlobalCompetence{inf}, ParameterError);
  EXPECT_THROW(GlobalCompetence(-1), ParameterError);
  EXPECT_THROW(LocalCompetence{std::nan("")}, ParameterError);
  EXPECT_NO_THROW(StaticCompetence(1.0));  // O(C) >= 1: the least competence allowed
}

// Each form's parameter is written once: the catalog lists competence_spec() and the policies
// refuse exactly the values outside its range.
TEST(CompetencePolicy, PoliciesCheckTheCatalogsRange) {
  const PlannerRegistry& registry = builtin_planners();
  const std::pair<CompetenceKind, const char*> forms[] = {
      {CompetenceKind::kStatic, "prm-c"}, {CompetenceKind::kGlobal, "prm-g"}, {CompetenceKind::kLocal, "prm-l"}};
  for (const auto& [kind, planner] : forms) {
    const core::ParamSpec& spec = competence_spec(kind);
    EXPECT_EQ(spec.name, competence_parameter(kind));
    EXPECT_EQ(registry.info(planner).params.front().name, spec.name);
    EXPECT_EQ(registry.info(planner).params.front().min, spec.min);
    EXPECT_EQ(registry.info(planner).params.front().max, spec.max);
    const auto make = [kind = kind](double v) -> std::unique_ptr<CompetencePolicy> {
      if (kind == CompetenceKind::kStatic) return std::make_unique<StaticCompetence>(v);
      if (kind == CompetenceKind::kGlobal) return std::make_unique<GlobalCompetence>(v);
      return std::make_unique<LocalCompetence>(v);
    };
    EXPECT_NO_THROW(make(spec.min));
    EXPECT_NO_THROW(make(spec.max));
    EXPECT_THROW(make(spec.min * 0.999), ParameterError);
    EXPECT_THROW(make(spec.max * 1.001), ParameterError);
    EXPECT_THROW(make(std::nan("")), ParameterError);
    EXPECT_THROW(registry.make(planner, {{spec.name, spec.max * 1.001}}), ParameterError);
  }
}

}  // namespace
}  // namespace amp::roadmap
