#include "amp/roadmap/run.hpp"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "amp/roadmap/prm/path_smoothing.hpp"
#include "amp/roadmap/prm/prm.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

constexpr double kTimeLimit = 60.0;

TEST(ExecuteRun, FillsTheRecord) {
  const world::Problem p = test::point_problem(true);
  const RunOutcome o = execute_run(p, "prm", {{"smooth", true}}, 17, kTimeLimit, 5000);
  const core::RunRecord& r = o.record;
  ASSERT_EQ(r.status, core::PlanStatus::kSolved) << r.message;
  EXPECT_EQ(r.planner, "prm");
  EXPECT_EQ(r.problem, "narrow_gap");
  EXPECT_EQ(r.seed, 17u);
  EXPECT_TRUE(r.message.empty());
  EXPECT_GT(r.cd_calls_planning, 0u);
  EXPECT_GT(r.cd_calls_query, 0u);  // smoothing
  EXPECT_EQ(r.cd_calls_training, 0u);
  // Certifying the path costs clearance calls; the path clearance is measured off the books.
  EXPECT_GT(r.clearance_calls, 0u);
  EXPECT_GE(r.extra.at("certified_segments"), 1.0);
  EXPECT_EQ(r.extra.at("refused_segments"), 0.0);
  EXPECT_GT(r.lp_calls, r.lp_successes);
  EXPECT_GT(r.lp_successes, 0u);
  ASSERT_NE(o.roadmap, nullptr);
  EXPECT_EQ(r.nodes, o.roadmap->vertex_count());
  EXPECT_EQ(r.edges, o.roadmap->edge_count());
  EXPECT_EQ(r.components, o.roadmap->component_count());
  EXPECT_EQ(r.path_states, o.path.size());
  EXPECT_DOUBLE_EQ(r.path_length, path_length(*p.space, o.path));
  // Shortest way round: (1,2) -> gap corner (4.5,4.6) -> (5.5,4.6) -> (9,2).
  EXPECT_GE(r.path_length, 2 * std::hypot(3.5, 2.6) + 1.0 - 1e-9);
  // The path passes through the gap, whose walls are 0.4 away from its centre line at most.
  EXPECT_GT(r.path_clearance, 0.0);
  EXPECT_LE(r.path_clearance, 0.4 + 1e-9);
  EXPECT_TRUE(r.extra.count("shortcuts"));
  EXPECT_GE(r.wall_time_s, 0.0);
}

TEST(ExecuteRun, DeterministicAndLimited) {
  const world::Problem p = test::point_problem(true);
  const RunOutcome a = execute_run(p, "prm", {}, 3, kTimeLimit, 5000);
  const RunOutcome b = execute_run(p, "prm", {}, 3, kTimeLimit, 5000);
  EXPECT_EQ(a.path, b.path);
  EXPECT_EQ(a.record.cd_calls(), b.record.cd_calls());
  EXPECT_EQ(a.record.path_clearance, b.record.path_clearance);

  const RunOutcome n = execute_run(test::point_problem(false), "prm", {{"k", 5}}, 3, kTimeLimit, 200);
  EXPECT_EQ(n.record.status, core::PlanStatus::kNodeLimit);
  EXPECT_EQ(n.record.nodes, 200u);
  EXPECT_EQ(n.record.path_states, 0u);
  EXPECT_EQ(n.record.path_length, 0.0);
  EXPECT_EQ(n.record.path_clearance, 0.0);
  EXPECT_TRUE(n.path.empty());
}

TEST(ExecuteRun, UserErrorsAreRethrown) {
  world::Problem p = test::point_problem(true);
  EXPECT_THROW(execute_run(p, "nope", {}, 1, kTimeLimit, 100), ParameterError);
  EXPECT_THROW(execute_run(p, "prm", {{"k", -1}}, 1, kTimeLimit, 100), ParameterError);
  p.seeds[0] = test::state2(5, 1);
  EXPECT_THROW(execute_run(p, "prm", {}, 1, kTimeLimit, 100), InvalidSeedError);
}

TEST(ExecuteRun, ProblemParametersApplyToPlannersThatDeclareThem) {
  world::Problem p = test::point_problem(true);
  p.defaults.params = {{"steps", "64"}, {"k", "3"}};
  const PlannerRegistry& reg = builtin_planners();
  // prm declares k but not steps; prm-l declares both; a run's own value wins.
  const core::ParamMap prm = with_problem_params(p, reg.info("prm"), {});
  EXPECT_EQ(prm, (core::ParamMap{{"k", "3"}}));
  const core::ParamMap l = with_problem_params(p, reg.info("prm-l"), {{"k", 5}});
  EXPECT_EQ(l, (core::ParamMap{{"k", 5}, {"steps", "64"}}));
  const RunOutcome o = execute_run(p, "prm-l", {}, 3, kTimeLimit, 3000);
  EXPECT_EQ(o.record.status, core::PlanStatus::kSolved);
  p.defaults.params = {{"steps", "0"}};  // a grid of zero steps: the user's error, said so
  EXPECT_THROW(execute_run(p, "prm-l", {}, 3, kTimeLimit, 3000), ParameterError);
  EXPECT_NO_THROW(execute_run(p, "prm", {}, 3, kTimeLimit, 3000));  // prm has no grid
}

class ThrowingPlanner final : public Planner {
 public:
  PlanResult plan(const PlanningContext&, const core::StopCondition&, core::Rng&) override {
    throw std::runtime_error("out of cheese");
  }
};

TEST(ExecuteRun, PlannerFailureIsAnErrorRecord) {
  PlannerRegistry r;
  r.add({{"bad", "throws", {}}}, [](const core::Params&) { return std::make_unique<ThrowingPlanner>(); });
  const RunOutcome o = execute_run(test::point_problem(true), "bad", {}, 1, kTimeLimit, 100, r);
  EXPECT_EQ(o.record.status, core::PlanStatus::kError);
  EXPECT_EQ(o.record.message, "out of cheese");
  EXPECT_TRUE(o.path.empty());
}

TEST(PathClearance, ByHand) {
  const world::Problem p = test::point_problem(true);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  // Along y = 5 from x = 1 to x = 4: nearest wall point is the gap's corner side x = 4.5 -> 0.5 at x = 4.
  const double c = path_clearance(*p.space, *checker, {test::state2(1, 5), test::state2(4, 5)});
  EXPECT_NEAR(c, std::hypot(0.5, 0.4), 1e-12);
  EXPECT_EQ(path_clearance(*p.space, *checker, {}), 0.0);
}

}  // namespace
}  // namespace amp::roadmap
