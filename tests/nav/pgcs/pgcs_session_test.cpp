#include "amp/nav/pgcs/pgcs_session.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/nav/polygon_nav_world.hpp"
#include "nav/pgcs/exploring.hpp"
#include "support/bundled_problems.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

PgcsRunSettings small_run(long steps, int queries) { return pgcs_test::short_run(steps, queries); }

learn::PgcsSettings small_pgcs() {
  learn::PgcsSettings p;
  p.max_clusters = 40;
  p.insert_every = 50;
  p.delete_every = 1000;
  return p;
}

// Every position the robot held is free for its disc in the world of that time (the world here
// does not change).
void expect_free(const NavWorld& world, const std::vector<V>& trace, double r) {
  for (const V& p : trace) ASSERT_TRUE(world.disc_free(p, r)) << p.transpose();
}

TEST(PgcsSession, ExplorationStaysFreeAndLearnsClusters) {
  const NavTask task = make_nav_task(test::bundled_problem("office-map.yaml"));
  PgcsSession s(task, small_run(3000, 0), small_pgcs(), 7);
  ASSERT_TRUE(s.explore(3000));
  EXPECT_EQ(s.steps(), 3000);
  EXPECT_GT(s.clusters().size(), 10);
  expect_free(*task.timeline->base(), s.exploration_trace(), task.robot_radius);
  ASSERT_GE(s.curves().size(), 10u);
  EXPECT_EQ(s.curves().front().step, 0);
  EXPECT_EQ(s.curves().back().step, 3000);
  for (const CurvePoint& c : s.curves()) {
    EXPECT_GE(c.coverage, 0.0);
    EXPECT_LE(c.coverage, 1.0);
    EXPECT_GE(c.quantisation_error, 0.0);
    EXPECT_NEAR(c.closed_prior, 0.0, 1e-12);  // nothing closes in this world
  }
}

// A box from (0, 0) to `corner` holding one polygon, a disc of 5 cm exploring from `start`.
NavTask polygon_task(const char* name, std::vector<V> polygon, V corner, V start) {
  world::Shapes2d s;
  s.polygons.push_back({std::move(polygon)});
  NavTask t;
  t.name = name;
  t.robot_radius = 0.05;
  t.start = start;
  t.goal = t.start;
  t.timeline = std::make_shared<const WorldTimeline>(
      std::make_shared<const PolygonNavWorld>(s, Eigen::AlignedBox2d(V(0, 0), corner)), std::vector<WorldEvent>{});
  return t;
}

// A 2 m x 1 m room with a box in its middle.
NavTask room_task() {
  return polygon_task("room", {{0.9, 0.35}, {1.1, 0.35}, {1.1, 0.65}, {0.9, 0.65}}, V(2, 1), V(0.3, 0.5));
}

TEST(PgcsSession, QueriesDriveFreePathsFromStartToTarget) {
  const NavTask task = room_task();
  PgcsSession s(task, small_run(6000, 8), small_pgcs(), 3);
  s.explore(6000);
  const auto pairs = s.draw_queries(8);
  ASSERT_EQ(pairs.size(), 8u);
  int solved = 0;
  for (const auto& [a, b] : pairs) {
    const QueryRecord q = s.query(a, b);
    ASSERT_FALSE(q.trace.empty());
    EXPECT_EQ(q.trace.front(), a);
    expect_free(*task.timeline->base(), q.trace, task.robot_radius);
    // A replan after every block, but the last one of a query given up (max_replans reached).
    const bool given_up = !q.solved && !q.unsolvable;
    EXPECT_EQ(q.blocks.size(), static_cast<std::size_t>(q.replans) + (given_up ? 1 : 0));
    EXPECT_LE(q.replans, 25);
    double length = 0.0;
    for (std::size_t i = 1; i < q.trace.size(); ++i) length += (q.trace[i] - q.trace[i - 1]).norm();
    EXPECT_NEAR(q.length, length, 1e-9 * (1 + length));
    if (q.solved) {
      ++solved;
      EXPECT_LT((q.trace.back() - b).norm(), 1e-9);  // it reached what it says it reached
      EXPECT_GT(q.ratio, 0.0);
    }
  }
  EXPECT_GT(solved, 0);
}

// Two 2 m x 2 m rooms side by side, joined by a 0.4 m door at the top of the wall between them.
NavTask two_rooms_task() {
  return polygon_task("two rooms", {{1.95, 0.0}, {2.05, 0.0}, {2.05, 1.6}, {1.95, 1.6}}, V(4, 2), V(0.5, 1.0));
}

TEST(PgcsSession, TraceLegsGoThroughTheDoorTheExplorerUsed) {
  // From the bottom of one room to the bottom of the other: the straight way is the wall. Driven
  // along the trace, the robot goes up through the door and down, without a block, and it turns
  // back nowhere: the driven length stays near the shortest.
  const NavTask task = two_rooms_task();
  for (std::uint64_t seed : {1, 2, 3}) {
    PgcsSession s(task, small_run(30000, 0), small_pgcs(), seed);
    s.explore(30000);
    const V a(0.5, 0.3), b(3.5, 0.3);
    const QueryRecord q = s.query(a, b);
    ASSERT_TRUE(q.solved) << "seed " << seed;
    EXPECT_EQ(q.replans, 0) << "seed " << seed;
    expect_free(*task.timeline->base(), q.trace, task.robot_radius);
    EXPECT_LT((q.trace.back() - b).norm(), 1e-9);
    EXPECT_GT(q.shortest, 4.0);  // up to the door and down again
    EXPECT_LT(q.ratio, 1.5) << "seed " << seed;
  }
}

TEST(PgcsSession, SameSeedSameRun) {
  const NavTask task = make_nav_task(test::bundled_problem("office-map.yaml"));
  auto run = [&] {
    PgcsSession s(task, small_run(2000, 3), small_pgcs(), 11);
    s.explore(2000);
    std::vector<double> out;
    for (int k : s.clusters().ids()) out.insert(out.end(), {s.clusters().mean(k).x(), s.clusters().mean(k).y()});
    for (const auto& [a, b] : s.draw_queries(3)) {
      const QueryRecord q = s.query(a, b);
      out.insert(out.end(), {q.length, static_cast<double>(q.replans), q.solved ? 1.0 : 0.0});
    }
    return out;
  };
  EXPECT_EQ(run(), run());
}

// A 2 m x 1 m room cut in two by a wall: the right half cannot be reached from the left.
NavTask split_task() {
  world::Shapes2d s;
  s.polygons.push_back({{{0.98, 0.0}, {1.02, 0.0}, {1.02, 1.0}, {0.98, 1.0}}});
  NavTask t;
  t.name = "split";
  t.robot_radius = 0.05;
  t.start = V(0.5, 0.5);
  t.goal = V(0.5, 0.5);
  t.timeline = std::make_shared<const WorldTimeline>(
      std::make_shared<const PolygonNavWorld>(s, Eigen::AlignedBox2d(V(0, 0), V(2, 1))), std::vector<WorldEvent>{});
  return t;
}

TEST(PgcsSession, UnconnectedQueryIsReportedNotSolved) {
  PgcsSession s(split_task(), small_run(2000, 0), small_pgcs(), 5);
  s.explore(2000);
  const QueryRecord q = s.query(V(0.5, 0.5), V(1.5, 0.5));
  EXPECT_FALSE(q.solved);
  EXPECT_TRUE(std::isinf(q.shortest));
  EXPECT_LT(q.trace.back().x(), 1.0);  // never through the wall
  // Queries drawn at random are all on the start's side.
  for (const auto& [a, b] : s.draw_queries(20)) EXPECT_TRUE(a.x() < 1.0 && b.x() < 1.0);
}

TEST(PgcsSession, QueryPointInAnObstacleOrOutsideIsAnError) {
  PgcsSession s(split_task(), small_run(100, 0), small_pgcs(), 5);
  s.explore(100);
  EXPECT_THROW(s.query(V(1.0, 0.5), V(0.5, 0.5)), ParameterError);
  EXPECT_THROW(s.query(V(0.5, 0.5), V(2.5, 0.5)), ParameterError);
}

TEST(PgcsSession, RejectsBadSettings) {
  PgcsRunSettings run = small_run(100, 0);
  run.speed = 0.0;
  EXPECT_THROW(PgcsSession(split_task(), run, small_pgcs(), 1), ParameterError);
  learn::PgcsSettings p = small_pgcs();
  p.max_clusters = 2;
  EXPECT_THROW(PgcsSession(split_task(), small_run(100, 0), p, 1), ParameterError);
  p = small_pgcs();
  p.window = 0;
  EXPECT_THROW(PgcsSession(split_task(), small_run(100, 0), p, 1), ParameterError);
}

}  // namespace
}  // namespace amp::nav
