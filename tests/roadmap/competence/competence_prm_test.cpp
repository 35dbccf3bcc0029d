#include "amp/roadmap/competence/competence_prm.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "support/path_checks.hpp"

#include "amp/core/error.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

struct Outcome {
  PlanResult result;
  std::uint64_t cd_planning = 0;
  std::uint64_t cd_query = 0;
};

Outcome run(const world::Problem& p, CompetencePrmSettings s, std::uint64_t seed, std::size_t node_limit = 3000) {
  core::Counters counters;
  counters.set_phase(core::Phase::kPlanning);
  const auto checker = p.environment->make_checker(counters);
  const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds};
  core::Rng rng(seed);
  const core::StopCondition stop(1e6, node_limit);
  CompetencePrm planner(s);
  Outcome o{planner.plan(ctx, stop, rng), counters.cd_calls(core::Phase::kPlanning),
            counters.cd_calls(core::Phase::kQuery)};
  return o;
}

CompetencePrmSettings settings(CompetenceKind kind, double value) {
  CompetencePrmSettings s;
  s.kind = kind;
  s.value = value;
  return s;
}

TEST(CompetencePrm, EveryFormSolvesTheGapWithAValidGridPath) {
  const world::Problem p = test::point_problem(true);
  // Every value of the metaplanner's sets.
  std::vector<CompetencePrmSettings> all;
  for (const auto kind : {CompetenceKind::kStatic, CompetenceKind::kGlobal, CompetenceKind::kLocal}) {
    for (const double v : metaplanner_values(kind)) all.push_back(settings(kind, v));
  }
  for (const auto& s : all) {
    for (std::uint64_t seed : {1u, 2u}) {
      const Outcome o = run(p, s, seed);
      ASSERT_EQ(o.result.status, core::PlanStatus::kSolved) << competence_parameter(s.kind) << " seed " << seed;
      amp::test::expect_valid_path(p, o.result.path, 2);
      EXPECT_EQ(o.result.components >= 1, true);
      EXPECT_EQ(o.result.extra.at(competence_parameter(s.kind)), s.value);
      EXPECT_GT(o.result.extra.at("astar_calls"), 0.0);
      EXPECT_EQ(o.cd_query, 0u);  // the path's grid states are replayed from stored moves, not searched
    }
  }
}

TEST(CompetencePrm, SameSeedSameRun) {
  const world::Problem p = test::arm_problem();
  for (const auto kind : {CompetenceKind::kStatic, CompetenceKind::kGlobal, CompetenceKind::kLocal}) {
    const auto s = settings(kind, metaplanner_values(kind)[1]);
    const Outcome a = run(p, s, 11), b = run(p, s, 11);
    ASSERT_EQ(a.result.status, core::PlanStatus::kSolved);
    amp::test::expect_valid_path(p, a.result.path, 2);
    EXPECT_EQ(a.cd_planning, b.cd_planning);
    EXPECT_EQ(a.result.nodes, b.result.nodes);
    EXPECT_EQ(a.result.path, b.result.path);
    EXPECT_EQ(a.result.extra, b.result.extra);
  }
}

TEST(CompetencePrm, ConnectsEverySeed) {
  world::Problem p = test::point_problem(true);
  p.seeds = {test::state2(1, 2), test::state2(9, 2), test::state2(1, 9), test::state2(9, 9)};
  const Outcome o = run(p, settings(CompetenceKind::kLocal, 0.1), 3);
  ASSERT_EQ(o.result.status, core::PlanStatus::kSolved);
  // The path visits the seeds in order.
  std::size_t next = 0;
  for (const State& s : o.result.path) {
    if (next < p.seeds.size() && s == p.seeds[next]) ++next;
  }
  EXPECT_EQ(next, p.seeds.size());
  const auto& roadmap = *o.result.roadmap;
  for (VertexId v = 1; v < 4; ++v) EXPECT_TRUE(roadmap.same_component(0, v));
}

TEST(CompetencePrm, UnsolvableRunStopsAtTheNodeLimit) {
  const world::Problem p = test::point_problem(false);
  const Outcome o = run(p, settings(CompetenceKind::kLocal, 0.1), 1, 200);
  EXPECT_EQ(o.result.status, core::PlanStatus::kNodeLimit);
  EXPECT_TRUE(o.result.path.empty());
}

}  // namespace
}  // namespace amp::roadmap
