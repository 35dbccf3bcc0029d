#include "amp/learn/kolmogorov.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <boost/math/distributions/normal.hpp>
#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::learn {
namespace {

// Sample of 30 values used with R 4.2.2 below.
const std::vector<double> kSample = {-2.31, -1.87, -1.52, -1.20, -0.95, -0.71, -0.60, -0.33, -0.12, 0.05,
                                     0.18,  0.40,  0.52,  0.77,  0.91,  1.10,  1.34,  1.58,  1.72,  1.96,
                                     2.15,  2.43,  2.80,  3.05,  3.41,  3.77,  4.20,  4.63,  5.10,  5.92};

template <typename Cdf>
std::vector<double> model_cdf(Cdf cdf) {
  std::vector<double> f;
  for (double x : kSample) f.push_back(cdf(x));
  return f;
}

TEST(Kolmogorov, TabulatedQuantiles) {
  // Classical table of the asymptotic Kolmogorov distribution (values rounded to 4 decimals).
  EXPECT_NEAR(kolmogorov_cdf(1.3581), 0.95, 1e-5);
  EXPECT_NEAR(kolmogorov_cdf(1.6276), 0.99, 1e-5);
  EXPECT_NEAR(kolmogorov_cdf(1.9495), 0.999, 1e-5);
  EXPECT_NEAR(kolmogorov_quantile(0.95), 1.3581, 1e-4);
  EXPECT_NEAR(kolmogorov_quantile(0.99), 1.6276, 1e-4);
  EXPECT_NEAR(kolmogorov_quantile(0.999), 1.9495, 1e-4);
}

TEST(Kolmogorov, BothSeriesAgreeAtTheSwitchAndQuantileInverts) {
  // The two series are different expansions of the same function: they must meet at x = 1.18.
  EXPECT_NEAR(kolmogorov_cdf(1.18 - 1e-12), kolmogorov_cdf(1.18), 1e-12);
  for (double x : {0.3, 0.6, 0.9, 1.1, 1.2, 1.5, 2.0, 3.0}) {
    EXPECT_NEAR(kolmogorov_cdf(x) + kolmogorov_sf(x), 1.0, 1e-15) << x;
    EXPECT_NEAR(kolmogorov_quantile(kolmogorov_cdf(x)), x, 1e-9) << x;
  }
  EXPECT_EQ(kolmogorov_cdf(0.0), 0.0);
  EXPECT_EQ(kolmogorov_cdf(-1.0), 0.0);
  // Deep left tail: the first theta term alone, sqrt(2 pi)/x exp(-pi^2/(8 x^2)) = 5.05e-13 at x = 0.2.
  EXPECT_NEAR(kolmogorov_cdf(0.2) / (std::sqrt(2.0 * std::numbers::pi) / 0.2 * std::exp(-std::numbers::pi * std::numbers::pi / 0.32)), 1.0, 1e-12);
  // Tail: 1 - K(x) ~ 2 exp(-2 x^2) with relative accuracy, no cancellation.
  EXPECT_NEAR(kolmogorov_sf(4.0) / (2.0 * std::exp(-32.0)), 1.0, 1e-12);
  EXPECT_EQ(kolmogorov_quantile(0.0), 0.0);
  EXPECT_TRUE(std::isinf(kolmogorov_quantile(1.0)));
  EXPECT_THROW(kolmogorov_quantile(1.5), ParameterError);
}

TEST(Kolmogorov, StatisticAndAsymptoticPValueMatchR) {
  const int n = static_cast<int>(kSample.size());
  // R 4.2.2:
  //   x <- c(-2.31, -1.87, ..., 5.92)   # kSample
  //   F <- function(q) 0.3*pnorm(q, -1, 0.8) + 0.7*pnorm(q, 2, 1.5)
  //   ks.test(x, F, exact = FALSE)   # D = 0.0834699691314951, p = 0.985016161569872
  //   ks.test(x, "pnorm", 0.5, 1, exact = FALSE)   # D = 0.294521629700773, p = 0.0109827171853265
  // R's asymptotic p is 1 - K(sqrt(n) D) (computed to 1e-6).
  const boost::math::normal a(-1.0, 0.8), b(2.0, 1.5), c(0.5, 1.0);
  const double d1 = ks_statistic(model_cdf([&](double x) { return 0.3 * cdf(a, x) + 0.7 * cdf(b, x); }));
  EXPECT_NEAR(d1, 0.0834699691314951, 1e-13);
  EXPECT_NEAR(kolmogorov_sf(std::sqrt(n) * d1), 0.985016161569872, 1e-6);
  const double d2 = ks_statistic(model_cdf([&](double x) { return cdf(c, x); }));
  EXPECT_NEAR(d2, 0.294521629700773, 1e-13);
  EXPECT_NEAR(kolmogorov_sf(std::sqrt(n) * d2), 0.0109827171853265, 1e-6);
  // Stephens' scaling makes the test slightly stricter than plain sqrt(n).
  EXPECT_LT(ks_p_value(d2, n), kolmogorov_sf(std::sqrt(n) * d2));
  EXPECT_NEAR(ks_p_value(d2, n), kolmogorov_sf((std::sqrt(30.0) + 0.12 + 0.11 / std::sqrt(30.0)) * d2), 1e-15);
}

TEST(Kolmogorov, CriticalValueIsTheQuantileOverStephensScale) {
  // n = 100, alpha = 0.001: 1.9495 / (10 + 0.12 + 0.011) = 0.19243.
  EXPECT_NEAR(ks_critical_value(100, 0.001), 1.9495 / 10.131, 2e-5);
  EXPECT_NEAR(ks_p_value(ks_critical_value(400, 0.001), 400), 0.001, 1e-12);
  EXPECT_THROW(ks_critical_value(100, 0.0), ParameterError);
  EXPECT_THROW(ks_critical_value(0, 0.01), ParameterError);
}

TEST(Kolmogorov, StatisticOfASingleValueAndOfAPerfectGrid) {
  // One point at F = 0.25: the ecdf jumps 0 -> 1 there, D = max(1 - 0.25, 0.25 - 0) = 0.75.
  EXPECT_DOUBLE_EQ(ks_statistic(std::vector<double>{0.25}), 0.75);
  // F(x_(i)) = (i - 0.5)/n, the best a model can do: D = 1/(2n).
  std::vector<double> grid;
  for (int i = 1; i <= 10; ++i) grid.push_back((i - 0.5) / 10.0);
  EXPECT_NEAR(ks_statistic(grid), 0.05, 1e-15);
}

}  // namespace
}  // namespace amp::learn
