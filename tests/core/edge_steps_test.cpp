#include "amp/core/edge_steps.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace amp::core {
namespace {

TEST(EdgeSegments, CeilOfDistanceOverResolutionAtLeastOne) {
  EXPECT_EQ(edge_segments(0.0, 0.1), 1);
  EXPECT_EQ(edge_segments(0.05, 0.1), 1);
  EXPECT_EQ(edge_segments(1.0, 0.25), 4);
  EXPECT_EQ(edge_segments(1.01, 0.25), 5);
  // Beyond int: 10^10 and 10^12 segments are counted, not wrapped (an int cast once gave 1).
  EXPECT_EQ(edge_segments(1.0, 1e-10), 10000000000LL);
  EXPECT_EQ(edge_segments(10.0, 1e-11), 1000000000000LL);
}

TEST(EdgeSegments, UnrepresentableCountsAreZero) {
  EXPECT_EQ(edge_segments(static_cast<double>(kMaxEdgeSegments), 1.0), kMaxEdgeSegments);
  EXPECT_EQ(edge_segments(2.0 * static_cast<double>(kMaxEdgeSegments), 1.0), 0);
  EXPECT_EQ(edge_segments(1.0, 1e-300), 0);
  EXPECT_EQ(edge_segments(1.0, 0.0), 0);  // infinite
  EXPECT_EQ(edge_segments(std::numeric_limits<double>::infinity(), 1.0), 0);
  EXPECT_EQ(edge_segments(std::numeric_limits<double>::quiet_NaN(), 1.0), 0);
  EXPECT_EQ(edge_segments(1.0, std::numeric_limits<double>::quiet_NaN()), 0);
}

}  // namespace
}  // namespace amp::core
