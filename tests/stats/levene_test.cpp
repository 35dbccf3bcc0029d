#include "amp/stats/levene_test.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::stats {
namespace {

// car is not installed, so the R reference is the definition (identical to car::leveneTest):
//   bf <- function(y, g, ctr) { z <- abs(y - ave(y, g, FUN = ctr)); anova(lm(z ~ g)) }
const Groups kGroups = {
    {12.1, 15.3, 9.8, 22.4, 13.0, 17.7, 11.2, 30.5},
    {8.4, 9.1, 7.7, 12.6, 10.2, 9.9, 8.8},
    {14.2, 25.8, 19.9, 41.3, 16.6, 21.0, 18.4, 28.7, 35.2},
};

TEST(LeveneTest, BrownForsytheMatchesR) {
  // R: bf(y, g, median): F = 2.600768342678934530, df 2 and 21, p = 0.097920040552037305
  const TestResult r = levene_test(kGroups);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.statistic, 2.600768342678934530, 1e-10);
  EXPECT_EQ(r.df1, 2.0);
  EXPECT_EQ(r.df2, 21.0);
  EXPECT_NEAR(r.p_value, 0.097920040552037305, 1e-12);
}

TEST(LeveneTest, MeanCentredOriginalMatchesR) {
  // R: bf(y, g, mean): F = 5.204164476262820749, p = 0.014599294556745933
  const TestResult r = levene_test(kGroups, LeveneCenter::kMean);
  EXPECT_NEAR(r.statistic, 5.204164476262820749, 1e-10);
  EXPECT_NEAR(r.p_value, 0.014599294556745933, 1e-12);
}

TEST(LeveneTest, TiedDataAndEvenGroupSizes) {
  // Even n: the median is the mean of the middle pair. R: ty <- c(1,2,2,3,3,3,5, 2,3,4,4,5,6,
  // 3,5,6,6,7,8,8,9); tg <- factor(rep(1:3, c(7, 6, 8))); bf(ty, tg, median):
  // F = 0.91525423728813460, df 2 and 18, p = 0.41826150421059904
  const Groups ties = {{1, 2, 2, 3, 3, 3, 5}, {2, 3, 4, 4, 5, 6}, {3, 5, 6, 6, 7, 8, 8, 9}};
  const TestResult r = levene_test(ties);
  EXPECT_NEAR(r.statistic, 0.91525423728813460, 1e-10);
  EXPECT_EQ(r.df2, 18.0);
  EXPECT_NEAR(r.p_value, 0.41826150421059904, 1e-12);
}

TEST(LeveneTest, RunCostSamples) {
  // R: cost <- function(gr, i) 1000 * exp(1.5 * sin(1.3 * i + gr) + 0.4 * gr * cos(0.7 * i));
  // bf over i = 0:239, gr = 1:3: F = 4.592989169215237588, df 2 and 717, p = 0.010422210658265815
  Groups g(3);
  for (int gr = 1; gr <= 3; ++gr) {
    for (int i = 0; i < 240; ++i) g[gr - 1].push_back(1000.0 * std::exp(1.5 * std::sin(1.3 * i + gr) + 0.4 * gr * std::cos(0.7 * i)));
  }
  const TestResult r = levene_test(g);
  EXPECT_NEAR(r.statistic, 4.592989169215237588, 1e-9);
  EXPECT_NEAR(r.p_value, 0.010422210658265815, 1e-10);
}

TEST(LeveneTest, DegenerateInputs) {
  // Constant groups: every deviation is 0, the F statistic 0 / 0.
  const TestResult constant = levene_test({{3.0, 3.0, 3.0}, {8.0, 8.0}});
  EXPECT_EQ(constant.status, TestStatus::kZeroVariance);
  EXPECT_TRUE(std::isnan(constant.p_value));
  // Groups of one: no error degrees of freedom.
  EXPECT_EQ(levene_test({{1.0}, {2.0}}).status, TestStatus::kTooFewObservations);
  EXPECT_THROW(levene_test({{1.0, 2.0}}), ParameterError);
  EXPECT_THROW(levene_test({{1.0, 2.0}, {}}), ParameterError);
}

}  // namespace
}  // namespace amp::stats
