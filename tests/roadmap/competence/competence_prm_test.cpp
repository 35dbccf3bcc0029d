#include "amp/roadmap/competence/competence_prm.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "support/path_checks.hpp"

#include "amp/core/error.hpp"
#include "amp/roadmap/prm/component_connection.hpp"
#include "roadmap/test_worlds.hpp"

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

TEST(ComponentNearestConnection, KNearestOfEachComponent) {
  const auto space = core::make_rn_space({0, 0}, {10, 10});
  Roadmap r;
  // Component A: x = 1, 2, 3, 4 on y = 0 (chained); B: x = 6, 7 on y = 0; C: the lone (5, 5).
  for (double x : {1.0, 2.0, 3.0, 4.0, 6.0, 7.0}) r.add_vertex(test::state2(x, 0));
  r.add_vertex(test::state2(5, 5));
  r.add_edge(0, 1, 1);
  r.add_edge(1, 2, 1);
  r.add_edge(2, 3, 1);
  r.add_edge(4, 5, 1);
  ComponentNearestConnection c(space, 2);
  for (VertexId v = 0; v < r.vertex_count(); ++v) c.add(v, r.state(v));
  const VertexId q = r.add_vertex(test::state2(5, 0));
  std::vector<Neighbor> out;
  c.candidates(r, q, out);
  std::vector<std::size_t> ids;
  for (const Neighbor& n : out) ids.push_back(n.index);
  // Nearest first: 4 (d 1, A), 3 (d 1, B), 2 (d 2, A), 5 (d 2, B), 6 (d 5, C); A's 1 and 0 dropped.
  EXPECT_EQ(ids, (std::vector<std::size_t>{3, 4, 2, 5, 6}));
  EXPECT_TRUE(std::is_sorted(out.begin(), out.end()));
}

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
