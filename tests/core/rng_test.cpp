#include "amp/core/rng.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "amp/core/stop_condition.hpp"

namespace amp::core {
namespace {

TEST(Rng, SameSeedSameStreamDifferentSeedDifferentStream) {
  Rng a(42), b(42), c(43);
  int differ = 0;
  for (int i = 0; i < 100; ++i) {
    const double x = a.uniform01();
    ASSERT_EQ(x, b.uniform01());
    differ += x != c.uniform01();
  }
  EXPECT_GT(differ, 95);
}

TEST(Rng, Mt19937_64FirstOutputMatchesTheStandard) {
  // [rand.predef]: the 10000th output of a default-constructed mt19937_64 is 9981545732273789042.
  Rng r(5489u);
  std::uint64_t x = 0;
  for (int i = 0; i < 10000; ++i) x = r.next_u64();
  EXPECT_EQ(x, 9981545732273789042ULL);
}

TEST(Rng, UniformAndNormalHaveTheRightMoments) {
  Rng r(1);
  constexpr int kN = 200000;
  double su = 0, sn = 0, sn2 = 0;
  for (int i = 0; i < kN; ++i) {
    const double u = r.uniform01();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    su += u;
    const double n = r.normal();
    sn += n;
    sn2 += n * n;
  }
  EXPECT_NEAR(su / kN, 0.5, 0.005);
  EXPECT_NEAR(sn / kN, 0.0, 0.01);
  EXPECT_NEAR(sn2 / kN, 1.0, 0.01);
}

TEST(Rng, UniformIndexCoversTheRange) {
  Rng r(9);
  int counts[7] = {};
  for (int i = 0; i < 70000; ++i) ++counts[r.uniform_index(7)];
  for (int c : counts) EXPECT_NEAR(c, 10000, 400);
}

TEST(Rng, DerivedSeedsDifferPerStream) {
  EXPECT_NE(derive_seed(1, 0), derive_seed(1, 1));
  EXPECT_NE(derive_seed(1, 0), derive_seed(2, 0));
  EXPECT_EQ(derive_seed(1, 5), derive_seed(1, 5));
}

TEST(StopCondition, NodeLimitAndCancelStopAtOnce) {
  std::atomic<bool> cancel{false};
  StopCondition stop(100.0, 10, &cancel);
  EXPECT_EQ(stop.check(9), StopReason::kNone);
  EXPECT_EQ(stop.check(10), StopReason::kNodeLimit);
  cancel = true;
  EXPECT_EQ(stop.check(0), StopReason::kCancelled);
}

TEST(StopCondition, ZeroTimeLimitStopsOnTheFirstCheck) {
  StopCondition stop(0.0, 1000);
  EXPECT_EQ(stop.check(0), StopReason::kTimeLimit);
}

}  // namespace
}  // namespace amp::core
