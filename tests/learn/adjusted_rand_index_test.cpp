#include "amp/learn/adjusted_rand_index.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::learn {
namespace {

using Labels = std::vector<int>;

TEST(AdjustedRandIndex, HandComputedTable) {
  // a = [0 0 1 2], b = [0 0 1 1]: sum C(n_ij,2) = 1, rows 2,1,1 -> 1, cols 2,2 -> 2, C(4,2) = 6,
  // E = 1 * 2 / 6 = 1/3, max = 1.5: ARI = (1 - 1/3) / (1.5 - 1/3) = 4/7.
  EXPECT_NEAR(adjusted_rand_index(Labels{0, 0, 1, 2}, Labels{0, 0, 1, 1}), 4.0 / 7.0, 1e-15);
  // Symmetric.
  EXPECT_NEAR(adjusted_rand_index(Labels{0, 0, 1, 1}, Labels{0, 0, 1, 2}), 4.0 / 7.0, 1e-15);
  // a = [0 0 1 1], b = [0 1 0 1]: table all ones, index 0, E = 2 * 2 / 6 = 2/3, max 2:
  // ARI = (0 - 2/3) / (2 - 2/3) = -1/2.
  EXPECT_NEAR(adjusted_rand_index(Labels{0, 0, 1, 1}, Labels{0, 1, 0, 1}), -0.5, 1e-15);
}

TEST(AdjustedRandIndex, InvariantToLabelNames) {
  EXPECT_DOUBLE_EQ(adjusted_rand_index(Labels{0, 0, 1, 1, 2}, Labels{2, 2, 0, 0, 1}), 1.0);
}

TEST(AdjustedRandIndex, TrivialPartitions) {
  EXPECT_DOUBLE_EQ(adjusted_rand_index(Labels{0, 0, 0}, Labels{0, 0, 0}), 1.0);
  EXPECT_DOUBLE_EQ(adjusted_rand_index(Labels{0, 1, 2}, Labels{2, 0, 1}), 1.0);
  // One cluster against all singletons: index 0, E = 3 * 0 / 3 = 0, max 1.5: ARI 0.
  EXPECT_DOUBLE_EQ(adjusted_rand_index(Labels{0, 0, 0}, Labels{0, 1, 2}), 0.0);
  EXPECT_DOUBLE_EQ(adjusted_rand_index(Labels{4}, Labels{0}), 1.0);
}

TEST(AdjustedRandIndex, RejectsBadInput) {
  EXPECT_THROW(adjusted_rand_index(Labels{0, 1}, Labels{0}), ParameterError);
  EXPECT_THROW(adjusted_rand_index(Labels{0, -1}, Labels{0, 0}), ParameterError);
}

}  // namespace
}  // namespace amp::learn
