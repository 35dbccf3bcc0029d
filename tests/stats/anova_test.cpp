#include "amp/stats/anova.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/stats/welch_anova.hpp"
#include "support/anova_groups.hpp"

namespace amp::stats {
namespace {

using test::cost_groups;  // support/anova_groups.hpp: groups with figures from R
using test::kGroups;

TEST(OneWayAnova, MatchesRAnovaLm) {
  // R: anova(lm(y ~ g)): SS 902.244047619047 / 1008.774285714286, MS 451.122023809524 /
  // 48.036870748299; oneway.test(y ~ g, var.equal = TRUE): F = 9.3911617634979922542, p = 0.0012205513990049097
  const AnovaTable t = one_way_anova(kGroups);
  EXPECT_NEAR(t.ss_between, 902.244047619047, 1e-9);
  EXPECT_NEAR(t.ss_within, 1008.774285714286, 1e-9);
  EXPECT_EQ(t.df_between, 2.0);
  EXPECT_EQ(t.df_within, 21.0);
  EXPECT_NEAR(t.ms_within, 48.036870748299, 1e-9);
  ASSERT_TRUE(t.test.ok());
  EXPECT_NEAR(t.test.statistic, 9.3911617634979922542, 1e-10);
  EXPECT_NEAR(t.test.p_value, 0.0012205513990049097, 1e-12);
  EXPECT_EQ(t.test.df1, 2.0);
  EXPECT_EQ(t.test.df2, 21.0);
}

TEST(OneWayAnova, MatchesROnRunCostSamples) {
  // R: oneway.test(ry ~ rg, var.equal = TRUE): F = 3.309502417962561616, df 2 and 717, p = 0.037093263430705826
  const AnovaTable t = one_way_anova(cost_groups());
  EXPECT_NEAR(t.test.statistic, 3.309502417962561616, 1e-9);
  EXPECT_EQ(t.test.df2, 717.0);
  EXPECT_NEAR(t.test.p_value, 0.037093263430705826, 1e-10);
}

TEST(OneWayAnova, ConstantGroupsGiveNaNWithAFlag) {
  // Every run of every planner cost the same: within variance 0, F = x / 0 -> flagged, not Inf.
  const Groups constant = {{5.0, 5.0, 5.0}, {7.0, 7.0}, {0.1, 0.1, 0.1}};
  const AnovaTable t = one_way_anova(constant);
  EXPECT_EQ(t.test.status, TestStatus::kZeroVariance);
  EXPECT_TRUE(std::isnan(t.test.statistic));
  EXPECT_TRUE(std::isnan(t.test.p_value));
  const TestResult w = welch_anova(constant);
  EXPECT_EQ(w.status, TestStatus::kZeroVariance);
  EXPECT_TRUE(std::isnan(w.p_value));
  // One constant group is enough to break Welch's weights n / s^2.
  EXPECT_EQ(welch_anova({{1.0, 2.0, 3.0}, {4.0, 4.0}}).status, TestStatus::kZeroVariance);
  EXPECT_TRUE(one_way_anova({{1.0, 2.0, 3.0}, {4.0, 4.0}}).test.ok());
}

TEST(OneWayAnova, GroupsOfOne) {
  // N = k: no error degrees of freedom.
  const AnovaTable t = one_way_anova({{1.0}, {2.0}, {4.0}});
  EXPECT_EQ(t.test.status, TestStatus::kTooFewObservations);
  EXPECT_TRUE(std::isnan(t.test.p_value));
  // A singleton beside larger groups is fine for the pooled test. R: y <- c(1, 2, 3, 10);
  // g <- factor(c(1, 1, 1, 2)); anova(lm(y ~ g)): F = 48 (SSB 48 on 1, SSW 2 on 2), p = 0.020204102886728765
  // (oneway.test refuses it: "not enough observations").
  const AnovaTable s = one_way_anova({{1.0, 2.0, 3.0}, {10.0}});
  ASSERT_TRUE(s.test.ok());
  EXPECT_NEAR(s.test.statistic, 48.0, 1e-12);
  EXPECT_NEAR(s.test.p_value, 0.020204102886728765, 1e-12);
  // but not for Welch, which needs a variance per group.
  EXPECT_EQ(welch_anova({{1.0, 2.0, 3.0}, {10.0}}).status, TestStatus::kTooFewObservations);
}

TEST(OneWayAnova, RejectsMalformedGroups) {
  EXPECT_THROW(one_way_anova({{1.0, 2.0}}), ParameterError);
  EXPECT_THROW(one_way_anova({{1.0, 2.0}, {}}), ParameterError);
  EXPECT_THROW(one_way_anova({{1.0, 2.0}, {NAN}}), ParameterError);
  EXPECT_THROW(welch_anova({{1.0, 2.0}}), ParameterError);
}

}  // namespace
}  // namespace amp::stats
