#include "amp/nav/pgcs/reference_worlds.hpp"

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "amp/learn/pgcs.hpp"
#include "nav/pgcs/exploring.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

TEST(ReferenceWorlds, CoverageAndErrorOfTheClustersOverTheReachableCells) {
  const NavTask task = pgcs_test::two_rooms();
  ReferenceWorlds worlds(task, 0.05);
  EXPECT_TRUE(worlds.start_has_room());
  learn::Pgcs none;
  EXPECT_EQ(worlds.coverage(none), 0.0);
  EXPECT_EQ(worlds.quantisation_error(none), 0.0);
  // One wide cluster in each room covers every reachable cell; its error is the RMS distance to it.
  learn::Pgcs wide;
  wide.add_cluster({1.0, 1.0}, 4.0, 0.5);
  wide.add_cluster({3.0, 1.0}, 4.0, 0.5);
  EXPECT_DOUBLE_EQ(worlds.coverage(wide), 1.0);
  const double e = worlds.quantisation_error(wide);
  EXPECT_GT(e, 0.3);
  EXPECT_LT(e, std::sqrt(2.0));
  // A narrow one covers a sliver.
  learn::Pgcs narrow;
  narrow.add_cluster({1.0, 1.0}, 0.01, 1.0);
  EXPECT_GT(worlds.coverage(narrow), 0.0);
  EXPECT_LT(worlds.coverage(narrow), 0.1);
}

TEST(ReferenceWorlds, NothingClosesInAWorldThatStaysAndTheOtherRoomIsReachable) {
  const NavTask task = pgcs_test::two_rooms();
  ReferenceWorlds worlds(task, 0.05);
  learn::Pgcs k;
  k.add_cluster({3.0, 0.5}, 0.1, 1.0);
  EXPECT_EQ(worlds.closed_prior(k, 1000), 0.0);
  const std::vector<std::uint8_t>& open = worlds.reachable_at(1000);
  EXPECT_NE(open[static_cast<std::size_t>(worlds.now().mask().cell_of(V(3.5, 0.5)))], 0);
  EXPECT_TRUE(std::isfinite(worlds.now().shortest_length(V(0.5, 0.3), V(3.5, 0.3))));
}

TEST(ReferenceWorlds, AStartWithNoRoomIsSeen) {
  NavTask task = pgcs_test::two_rooms();
  task.start = V(10.0, 10.0);  // outside the world
  EXPECT_FALSE(ReferenceWorlds(task, 0.05).start_has_room());
}

}  // namespace
}  // namespace amp::nav
