#include "amp/nav/pgcs/pgcs_explorer.hpp"

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "nav/pgcs/exploring.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;
using pgcs_test::Exploring;

TEST(PgcsExplorer, SameSeedSameClustersAndPositions) {
  Exploring a(3), b(3);
  a.explore(3000);
  b.explore(3000);
  EXPECT_EQ(a.explorer.steps(), 3000);
  ASSERT_EQ(a.explorer.clusters().ids(), b.explorer.clusters().ids());
  for (int k : a.explorer.clusters().ids()) EXPECT_EQ(a.explorer.clusters().mean(k), b.explorer.clusters().mean(k));
  EXPECT_EQ(a.explorer.positions(), b.explorer.positions());
  EXPECT_GT(a.explorer.clusters().size(), 5);
  EXPECT_GT(a.corridor.visited_count(), 0u);
}

TEST(PgcsExplorer, NodePointsArePositionsTheRobotHeld) {
  Exploring e(5);
  e.explore(4000);
  e.explorer.adopt_exemplars();
  int with_point = 0;
  for (int k : e.explorer.clusters().ids()) {
    const V p = e.explorer.node_point(k);
    if (!p.allFinite()) continue;
    ++with_point;
    EXPECT_TRUE(e.task.timeline->base()->disc_free(p, e.task.robot_radius)) << p.transpose();
  }
  EXPECT_GT(with_point, 0);
}

TEST(PgcsExplorer, PortalsAreKnownOnlyWhenOnAndDroppedOnRequest) {
  Exploring off(7, false);
  off.explore(4000);
  for (int a : off.explorer.clusters().ids()) {
    for (int b : off.explorer.clusters().ids()) EXPECT_EQ(off.explorer.portal(a, b), nullptr);
  }
  Exploring on(7);
  on.explore(4000);
  int a = -1, b = -1;
  for (int k : on.explorer.clusters().ids()) {
    for (int j : on.explorer.portals().crossed(k)) {
      if (on.explorer.portal(k, j) != nullptr) a = k, b = j;
    }
  }
  ASSERT_GE(a, 0);
  const std::uint64_t before = on.explorer.revision();
  on.explorer.drop_portal(a, b);
  EXPECT_EQ(on.explorer.portal(a, b), nullptr);
  EXPECT_NE(on.explorer.revision(), before);  // the graphs on it see the change
}

TEST(PgcsExplorer, RevisionChangesWithEveryStepAndAdoption) {
  Exploring e(2);
  e.explore(200);
  std::uint64_t r = e.explorer.revision();
  e.explore(1);
  EXPECT_NE(e.explorer.revision(), r);
  r = e.explorer.revision();
  e.explorer.adopt_exemplars();
  EXPECT_NE(e.explorer.revision(), r);
  r = e.explorer.revision();
  e.explorer.adopt_exemplars();  // the clusters stood still: nothing to adopt
  EXPECT_EQ(e.explorer.revision(), r);
}

TEST(PgcsExplorer, RejectsBadPgcsSettings) {
  const NavTask task = pgcs_test::two_rooms();
  learn::PgcsSettings p;
  p.window = 0;
  EXPECT_THROW(PgcsExplorer(task, PgcsRunSettings{}, p, core::Rng(1)), ParameterError);
}

}  // namespace
}  // namespace amp::nav
