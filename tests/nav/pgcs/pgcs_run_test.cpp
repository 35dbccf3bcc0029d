#include "amp/nav/pgcs/pgcs_run.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/pgcs/pgcs_navigator.hpp"
#include "nav/pgcs/exploring.hpp"
#include "support/bundled_problems.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

PgcsRunSettings small_run(long steps, int queries) { return pgcs_test::short_run(steps, queries); }

TEST(PgcsRun, TheNavigatorIsTheSameLoop) {
  // `pgcs` in amp bench and amp explore share run_pgcs: with the seed the navigator draws, the
  // summary of run_pgcs is the navigator's record.
  const NavTask task = make_nav_task(test::bundled_problem("office-map.yaml"));
  const PgcsRunSettings run = small_run(4000, 3);
  const learn::PgcsSettings pgcs;
  core::Rng rng(5);
  core::StopCondition stop(600.0, static_cast<std::size_t>(-1));
  PgcsNavigator navigator(run, pgcs);
  const NavigationOutcome outcome = navigator.run(task, stop, rng);
  const PgcsRun direct = run_pgcs(task, run, pgcs, core::Rng(5).next_u64());
  EXPECT_FALSE(direct.stopped);
  ASSERT_EQ(direct.queries.size(), 3u);
  EXPECT_EQ(direct.query_wall_s.size(), 3u);
  EXPECT_EQ(outcome.record.extra, pgcs_metrics(summarise_pgcs(*direct.session, direct.queries)));
}

TEST(PgcsRun, SummaryCountsByHandAndLeavesOutMediansOfNoSample) {
  const NavTask task = make_nav_task(test::bundled_problem("office-map.yaml"));
  const PgcsRun r = run_pgcs(task, small_run(2000, 0), learn::PgcsSettings{}, 3);
  PgcsSummary s = summarise_pgcs(*r.session, r.queries);
  EXPECT_EQ(s.steps, 2000);
  EXPECT_EQ(s.queries, 0u);
  EXPECT_FALSE(s.replans_median.has_value());
  EXPECT_FALSE(s.path_ratio_median.has_value());
  std::map<std::string, double> m = pgcs_metrics(s);
  EXPECT_FALSE(m.contains("replans_median"));
  EXPECT_FALSE(m.contains("path_ratio_median"));
  EXPECT_EQ(m.at("solved_fraction"), 0.0);

  // Three queries made by hand: replans 0, 3, 1 (median 1, max 3, total 4); ratios of the two
  // solved 1.2 and 1.0 (median 1.1).
  std::vector<QueryRecord> q(3);
  q[0].replans = 0, q[0].solved = true, q[0].ratio = 1.2;
  q[1].replans = 3, q[1].solved = false;
  q[2].replans = 1, q[2].solved = true, q[2].ratio = 1.0;
  s = summarise_pgcs(*r.session, q);
  EXPECT_EQ(s.queries_solved, 2);
  EXPECT_EQ(s.replans_max, 3);
  EXPECT_DOUBLE_EQ(s.replans_total, 4.0);
  EXPECT_DOUBLE_EQ(*s.replans_median, 1.0);
  EXPECT_DOUBLE_EQ(*s.path_ratio_median, 1.1);
  m = pgcs_metrics(s);
  EXPECT_DOUBLE_EQ(m.at("solved_fraction"), 2.0 / 3.0);
}

TEST(PgcsRun, AGivenQueryItCannotDriveNamesItsIndex) {
  const NavTask task = make_nav_task(test::bundled_problem("office-map.yaml"));
  const Eigen::AlignedBox2d b = task.timeline->base()->bounds();
  const V outside = b.max() + V(5, 5);
  const QueryPairs given = {{task.start, task.start}, {task.start, outside}};
  try {
    run_pgcs(task, small_run(500, 0), learn::PgcsSettings{}, 1, given);
    FAIL() << "expected PgcsQueryError";
  } catch (const PgcsQueryError& e) {
    EXPECT_EQ(e.index(), 1u);
    EXPECT_EQ(std::string(e.what()).rfind("query 2: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace amp::nav
