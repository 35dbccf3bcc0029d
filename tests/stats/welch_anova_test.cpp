// welch_anova.cpp: Welch's one-way ANOVA for unequal variances.
#include "amp/stats/welch_anova.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "support/anova_groups.hpp"

namespace amp::stats {
namespace {

using test::cost_groups;
using test::kGroups;

TEST(WelchAnova, MatchesROnewayTestUnequalVariances) {
  // R: oneway.test(y ~ g, var.equal = FALSE): F = 14.267234925372751, df 2 and 10.883653222338454, p = 9.0875642246921893e-04
  const TestResult r = welch_anova(kGroups);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.statistic, 14.267234925372751, 1e-10);
  EXPECT_EQ(r.df1, 2.0);
  EXPECT_NEAR(r.df2, 10.883653222338454, 1e-10);
  EXPECT_NEAR(r.p_value, 9.0875642246921893e-04, 1e-12);
  // R: oneway.test(ry ~ rg, var.equal = FALSE): F = 3.062062890430899742, df2 = 452.377969750964609830, p = 0.047762162501938016
  const TestResult c = welch_anova(cost_groups());
  EXPECT_NEAR(c.statistic, 3.062062890430899742, 1e-9);
  EXPECT_NEAR(c.df2, 452.377969750964609830, 1e-7);
  EXPECT_NEAR(c.p_value, 0.047762162501938016, 1e-10);
}

// Two groups: Welch's F is the square of Welch's t, and df2 the Welch-Satterthwaite degrees of
// freedom, both by hand: means 2.5 and 5, variances 5/3 and 4, sizes 4 and 3.
TEST(WelchAnova, TwoGroupsGiveTheSquareOfWelchsT) {
  const TestResult r = welch_anova({{1, 2, 3, 4}, {3, 5, 7}});
  ASSERT_TRUE(r.ok());
  const double se2 = (5.0 / 3.0) / 4.0 + 4.0 / 3.0;
  const double t = (5.0 - 2.5) / std::sqrt(se2);
  EXPECT_NEAR(r.statistic, t * t, 1e-12);
  EXPECT_EQ(r.df1, 1.0);
  const double a = (5.0 / 3.0) / 4.0, b = 4.0 / 3.0;
  EXPECT_NEAR(r.df2, se2 * se2 / (a * a / 3.0 + b * b / 2.0), 1e-12);
  EXPECT_GT(r.p_value, 0.05);  // t = 1.89 on 3.2 df: not significant
  EXPECT_LT(r.p_value, 0.5);
  // Equal means: F = 0, p = 1.
  const TestResult same = welch_anova({{1, 2, 3}, {0, 2, 4}});
  ASSERT_TRUE(same.ok());
  EXPECT_NEAR(same.statistic, 0.0, 1e-15);
  EXPECT_NEAR(same.p_value, 1.0, 1e-12);
}

}  // namespace
}  // namespace amp::stats
