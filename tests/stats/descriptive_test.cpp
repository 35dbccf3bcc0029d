#include "amp/stats/descriptive.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::stats {
namespace {

// Heavy-tailed, run-cost-like samples that R and C++ compute identically from a formula:
//   cost <- function(gr, i) 1000 * exp(1.5 * sin(1.3 * i + gr) + 0.4 * gr * cos(0.7 * i)); i <- 0:239
std::vector<double> cost_sample(int group) {
  std::vector<double> x;
  for (int i = 0; i < 240; ++i) x.push_back(1000.0 * std::exp(1.5 * std::sin(1.3 * i + group) + 0.4 * group * std::cos(0.7 * i)));
  return x;
}

const std::vector<double> kG1 = {12.1, 15.3, 9.8, 22.4, 13.0, 17.7, 11.2, 30.5};

TEST(Describe, MatchesRMeanSdQuantilesType7) {
  // R: c(mean(g1), sd(g1), 100 * sd(g1) / mean(g1), quantile(g1, c(0, .25, .5, .75, 1)))
  const Summary s = describe(kG1);
  EXPECT_EQ(s.n, 8u);
  EXPECT_NEAR(s.mean, 16.5, 1e-12);
  EXPECT_NEAR(s.std_dev, 6.9516698918831210, 1e-12);
  EXPECT_NEAR(s.cv_percent, 42.1313326780795165, 1e-10);
  EXPECT_EQ(s.min, 9.8);
  EXPECT_NEAR(s.q1, 11.875, 1e-12);
  EXPECT_NEAR(s.median, 14.15, 1e-12);
  EXPECT_NEAR(s.q3, 18.875, 1e-12);
  EXPECT_EQ(s.max, 30.5);
}

TEST(Describe, ConfidenceIntervalOfTheMeanMatchesRsTTest) {
  // R: t.test(g1)$conf.int, i.e. mean -+ qt(.975, 7) sd / sqrt(8) with qt(.975, 7) = 2.364624251592785.
  const Summary s = describe(kG1);
  EXPECT_NEAR(s.ci95_low, 10.688258530122356, 1e-9);
  EXPECT_NEAR(s.ci95_high, 22.311741469877646, 1e-9);
  // R: t.test(1:5)$conf.int = 1.036757 4.963243.
  const Summary five = describe(std::vector<double>{1, 2, 3, 4, 5});
  EXPECT_NEAR(five.ci95_low, 1.036757, 1e-6);
  EXPECT_NEAR(five.ci95_high, 4.963243, 1e-6);
  EXPECT_TRUE(std::isnan(describe(std::vector<double>{2.0}).ci95_low));  // no interval from one value
}

TEST(Describe, MatchesROnRunCostSample) {
  // R: c(mean(x), sd(x), quantile(x, c(0, .25, .5, .75, 1))) for cost(1, 0:239)
  const Summary s = describe(cost_sample(1));
  EXPECT_EQ(s.n, 240u);
  EXPECT_NEAR(s.mean, 1719.36339159374234, 1e-9);
  EXPECT_NEAR(s.std_dev, 1658.45462897394782, 1e-9);
  EXPECT_NEAR(s.min, 150.73170782505994, 1e-9);
  EXPECT_NEAR(s.q1, 361.21160730681322, 1e-9);
  EXPECT_NEAR(s.median, 957.37999456808643, 1e-9);
  EXPECT_NEAR(s.q3, 2764.99641368864786, 1e-9);
  EXPECT_NEAR(s.max, 6524.72129252022478, 1e-9);
}

TEST(Quantile, Type7InterpolatesBetweenOrderStatistics) {
  // g3 sorted; R: quantile(g3, c(.1, .25, .5, .75, .9)) = 16.12 18.4 21.0 28.7 36.42
  const std::vector<double> g3 = {14.2, 16.6, 18.4, 19.9, 21.0, 25.8, 28.7, 35.2, 41.3};
  EXPECT_NEAR(quantile(g3, 0.10), 16.12, 1e-12);  // h = 0.8: 14.2 + 0.8 * (16.6 - 14.2)
  EXPECT_NEAR(quantile(g3, 0.25), 18.4, 1e-12);   // h = 2 exactly
  EXPECT_NEAR(quantile(g3, 0.50), 21.0, 1e-12);
  EXPECT_NEAR(quantile(g3, 0.75), 28.7, 1e-12);
  EXPECT_NEAR(quantile(g3, 0.90), 36.42, 1e-12);
  EXPECT_EQ(quantile(g3, 0.0), 14.2);
  EXPECT_EQ(quantile(g3, 1.0), 41.3);
  const std::vector<double> one = {7.0};
  EXPECT_EQ(quantile(one, 0.3), 7.0);
  EXPECT_THROW(quantile(std::vector<double>{}, 0.5), ParameterError);
  EXPECT_THROW(quantile(g3, 1.5), ParameterError);
}

TEST(Describe, EdgeCases) {
  const Summary empty = describe(std::vector<double>{});
  EXPECT_EQ(empty.n, 0u);
  EXPECT_TRUE(std::isnan(empty.mean));
  EXPECT_TRUE(std::isnan(empty.median));

  const Summary one = describe(std::vector<double>{5.0});
  EXPECT_EQ(one.mean, 5.0);
  EXPECT_TRUE(std::isnan(one.std_dev));  // as R's sd() of one value
  EXPECT_TRUE(std::isnan(one.cv_percent));
  EXPECT_EQ(one.q1, 5.0);
  EXPECT_EQ(one.q3, 5.0);

  // Large values with a small spread: the two-pass variance keeps every digit.
  const Summary close = describe(std::vector<double>{1e9 + 1.0, 1e9 + 2.0, 1e9 + 3.0});
  EXPECT_DOUBLE_EQ(close.std_dev, 1.0);

  const Summary zero_mean = describe(std::vector<double>{-1.0, 1.0});
  EXPECT_TRUE(std::isnan(zero_mean.cv_percent));

  EXPECT_THROW(describe(std::vector<double>{1.0, std::nan("")}), ParameterError);
}

TEST(Median, MatchesRsMedianAndHasNoneForAnEmptySample) {
  // R: median(c(3, 1, 2)) = 2; median(c(4, 1, 3, 2)) = 2.5; median(c(0.1, 0.7, 0.2, 0.4)) = 0.3.
  EXPECT_DOUBLE_EQ(*median(std::vector<double>{3, 1, 2}), 2.0);
  EXPECT_DOUBLE_EQ(*median(std::vector<double>{4, 1, 3, 2}), 2.5);
  EXPECT_DOUBLE_EQ(*median(std::vector<double>{0.1, 0.7, 0.2, 0.4}), 0.3);
  EXPECT_FALSE(median(std::vector<double>{}).has_value());
}

}  // namespace
}  // namespace amp::stats
