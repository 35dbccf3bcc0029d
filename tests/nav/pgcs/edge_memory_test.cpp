#include "amp/nav/pgcs/edge_memory.hpp"

#include <gtest/gtest.h>

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

TEST(EdgeMemory, OneStrikeIsThePapersIllegalEdge) {
  EdgeMemory m(0.1);
  EXPECT_FALSE(m.illegal(1, 2, V(0, 0), V(1, 0)));
  m.mark(2, 1, V(1, 0), V(0, 0));  // either order
  EXPECT_TRUE(m.illegal(1, 2, V(0, 0), V(1, 0)));
  EXPECT_TRUE(m.illegal(2, 1, V(1, 0), V(0, 0)));
  EXPECT_EQ(m.size(), 1u);
  ASSERT_EQ(m.entries().size(), 1u);
  EXPECT_EQ(m.entries()[0].a, 1);
  EXPECT_EQ(m.entries()[0].pb, V(1, 0));
}

TEST(EdgeMemory, BlocksCountUpToTheStrikes) {
  EdgeMemory m(0.1, 2);
  m.mark(1, 2, V(0, 0), V(1, 0));
  EXPECT_EQ(m.blocks(1, 2, V(0, 0), V(1, 0)), 1);
  EXPECT_FALSE(m.illegal(1, 2, V(0, 0), V(1, 0)));  // a suspect
  EXPECT_EQ(m.size(), 0u);
  EXPECT_EQ(m.suspects(), 1u);
  ASSERT_EQ(m.entries().size(), 1u);
  EXPECT_EQ(m.entries()[0].blocks, 1);
  m.mark(1, 2, V(0.05, 0), V(1, 0));  // within the tolerance: the same edge
  EXPECT_EQ(m.blocks(1, 2, V(0, 0), V(1, 0)), 2);
  EXPECT_TRUE(m.illegal(1, 2, V(0, 0), V(1, 0)));
  EXPECT_EQ(m.size(), 1u);
  EXPECT_EQ(m.suspects(), 0u);
  EXPECT_EQ(m.entries()[0].blocks, 2);
}

TEST(EdgeMemory, AnEdgeWhoseEndsMovedStartsAfresh) {
  EdgeMemory m(0.1, 2);
  m.mark(1, 2, V(0, 0), V(1, 0));
  EXPECT_EQ(m.blocks(1, 2, V(0, 0), V(1.5, 0)), 0);  // cluster 2 moved 0.5 > 0.1
  m.mark(1, 2, V(0, 0), V(1.5, 0));
  EXPECT_EQ(m.blocks(1, 2, V(0, 0), V(1.5, 0)), 1);  // one block of the new edge, not two
  m.clear();
  EXPECT_EQ(m.blocks(1, 2, V(0, 0), V(1.5, 0)), 0);
}

TEST(EdgeMemory, EdgesOfUnmarkedClustersAndBeyondTheLargestIdAreFree) {
  EdgeMemory m(0.1);
  m.mark(3, 7, V(0, 0), V(1, 0));
  m.mark(-1, 5, V(2, 0), V(3, 0));  // a negative id (a route's start) is kept too
  EXPECT_TRUE(m.illegal(7, 3, V(1, 0), V(0, 0)));
  EXPECT_TRUE(m.illegal(5, -1, V(3, 0), V(2, 0)));
  EXPECT_EQ(m.blocks(3, 5, V(0, 0), V(3, 0)), 0);     // both ids marked, not this edge
  EXPECT_EQ(m.blocks(3, 4, V(0, 0), V(1, 0)), 0);     // 4 never marked
  EXPECT_EQ(m.blocks(3, 1000, V(0, 0), V(1, 0)), 0);  // beyond every id marked
  m.clear();
  EXPECT_EQ(m.blocks(3, 7, V(0, 0), V(1, 0)), 0);
  m.mark(7, 3, V(1, 0), V(0, 0));
  EXPECT_TRUE(m.illegal(3, 7, V(0, 0), V(1, 0)));
}

}  // namespace
}  // namespace amp::nav
