#include "amp/stats/kruskal_wallis.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::stats {
namespace {

TEST(AverageRanks, TiesShareTheMeanRank) {
  // R: rank(c(1,2,2,3,3,3,5, 2,3,4,4,5,6, 3,5,6,6,7,8,8,9))
  const std::vector<double> x = {1, 2, 2, 3, 3, 3, 5, 2, 3, 4, 4, 5, 6, 3, 5, 6, 6, 7, 8, 8, 9};
  const std::vector<double> expected = {1.0, 3.0, 3.0, 7.0, 7.0, 7.0, 13.0, 3.0, 7.0, 10.5, 10.5,
                                        13.0, 16.0, 7.0, 13.0, 16.0, 16.0, 18.0, 19.5, 19.5, 21.0};
  EXPECT_EQ(average_ranks(x), expected);
}

TEST(KruskalWallis, MatchesRWithoutTies) {
  // R: kruskal.test(y ~ g) on the data below: chi-squared = 14.621428571428581, df = 2, p = 6.6833949618199263e-04
  const Groups g = {
      {12.1, 15.3, 9.8, 22.4, 13.0, 17.7, 11.2, 30.5},
      {8.4, 9.1, 7.7, 12.6, 10.2, 9.9, 8.8},
      {14.2, 25.8, 19.9, 41.3, 16.6, 21.0, 18.4, 28.7, 35.2},
  };
  const TestResult r = kruskal_wallis(g);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.statistic, 14.621428571428581, 1e-10);
  EXPECT_EQ(r.df1, 2.0);
  EXPECT_TRUE(std::isnan(r.df2));
  EXPECT_NEAR(r.p_value, 6.6833949618199263e-04, 1e-12);
}

TEST(KruskalWallis, MatchesRWithTieCorrection) {
  // R: kruskal.test(ty ~ tg): chi-squared = 10.9334092202618116, df = 2, p = 0.0042251327010617767
  const Groups g = {{1, 2, 2, 3, 3, 3, 5}, {2, 3, 4, 4, 5, 6}, {3, 5, 6, 6, 7, 8, 8, 9}};
  const TestResult r = kruskal_wallis(g);
  EXPECT_NEAR(r.statistic, 10.9334092202618116, 1e-10);
  EXPECT_NEAR(r.p_value, 0.0042251327010617767, 1e-12);
}

TEST(KruskalWallis, RunCostSamples) {
  // R: kruskal.test over cost(gr, 0:239), gr = 1:3 (see support/anova_groups.hpp):
  // chi-squared = 0.028651756818817375, p = 0.985776248718099546
  Groups g(3);
  for (int gr = 1; gr <= 3; ++gr) {
    for (int i = 0; i < 240; ++i) g[gr - 1].push_back(1000.0 * std::exp(1.5 * std::sin(1.3 * i + gr) + 0.4 * gr * std::cos(0.7 * i)));
  }
  const TestResult r = kruskal_wallis(g);
  EXPECT_NEAR(r.statistic, 0.028651756818817375, 1e-10);
  EXPECT_NEAR(r.p_value, 0.985776248718099546, 1e-10);
}

TEST(KruskalWallis, AllTiedIsFlagged) {
  // Every value equal: H = 0 / 0 (R gives NaN too).
  const TestResult r = kruskal_wallis({{4.0, 4.0}, {4.0, 4.0, 4.0}});
  EXPECT_EQ(r.status, TestStatus::kZeroVariance);
  EXPECT_TRUE(std::isnan(r.statistic));
  EXPECT_TRUE(std::isnan(r.p_value));
  EXPECT_THROW(kruskal_wallis({{1.0}}), ParameterError);
}

}  // namespace
}  // namespace amp::stats
