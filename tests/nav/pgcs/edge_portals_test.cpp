#include "amp/nav/pgcs/edge_portals.hpp"

#include <gtest/gtest.h>

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

TEST(EdgePortals, KeepsTheRunningMeanOfCrossingsPerPair) {
  EdgePortals p(100);
  p.observe(4, 10, 2, 20, V(1, 0));
  p.observe(2, 20, 4, 10, V(3, 2));  // the same pair, the other way round
  const V* gate = p.find(2, 20, 4, 10);
  ASSERT_NE(gate, nullptr);
  EXPECT_EQ(*gate, V(2, 1));
  EXPECT_EQ(p.find(4, 10, 2, 20), gate);
  EXPECT_EQ(p.crossed(2), std::vector<int>{4});
  EXPECT_EQ(p.crossed(4), std::vector<int>{2});
  EXPECT_TRUE(p.crossed(9).empty());
}

TEST(EdgePortals, MemoryBoundsTheWeightOfOldCrossings) {
  EdgePortals p(2);  // at most the last two crossings' weight: m += (x - m) / 2 from the second on
  p.observe(0, 0, 1, 0, V(0, 0));
  p.observe(0, 0, 1, 0, V(4, 0));  // (0 + 4) / 2 = 2
  p.observe(0, 0, 1, 0, V(8, 0));  // 2 + (8 - 2) / 2 = 5
  EXPECT_EQ(*p.find(0, 0, 1, 0), V(5, 0));
}

TEST(EdgePortals, ReusedIdDoesNotInheritAPortal) {
  EdgePortals p(100);
  p.observe(0, 5, 1, 5, V(1, 1));
  EXPECT_EQ(p.find(0, 5, 1, 7), nullptr);  // cluster 1 was deleted and its id reused at step 7
  p.observe(0, 5, 1, 7, V(3, 3));           // the new pair starts afresh
  EXPECT_EQ(*p.find(0, 5, 1, 7), V(3, 3));
  EXPECT_EQ(p.find(0, 5, 1, 5), nullptr);
  EXPECT_EQ(p.crossed(0), std::vector<int>{1});
}

TEST(EdgePortals, ForgetDropsEveryPairOfACluster) {
  EdgePortals p(100);
  p.observe(0, 1, 1, 1, V(1, 0));
  p.observe(1, 1, 2, 1, V(2, 0));
  p.observe(0, 1, 2, 1, V(3, 0));
  p.forget(1);
  EXPECT_EQ(p.find(0, 1, 1, 1), nullptr);
  EXPECT_EQ(p.find(1, 1, 2, 1), nullptr);
  EXPECT_EQ(*p.find(0, 1, 2, 1), V(3, 0));
  EXPECT_EQ(p.size(), 1u);
  EXPECT_EQ(p.crossed(0), std::vector<int>{2});
  EXPECT_EQ(p.crossed(2), std::vector<int>{0});
  EXPECT_TRUE(p.crossed(1).empty());
  p.forget(7);  // never seen: nothing to drop
  EXPECT_EQ(p.size(), 1u);
}

TEST(EdgePortals, DropRemovesOnePair) {
  EdgePortals p(100);
  p.observe(0, 1, 1, 1, V(1, 0));
  p.observe(0, 1, 2, 1, V(3, 0));
  p.drop(1, 0);
  EXPECT_EQ(p.find(0, 1, 1, 1), nullptr);
  EXPECT_EQ(*p.find(0, 1, 2, 1), V(3, 0));
  EXPECT_EQ(p.crossed(0), std::vector<int>{2});
  EXPECT_TRUE(p.crossed(1).empty());
  p.drop(0, 1);  // already gone
  EXPECT_EQ(p.size(), 1u);
}

}  // namespace
}  // namespace amp::nav
