#include "amp/stats/histogram.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::stats {
namespace {

std::vector<double> cost_sample(int group) {  // as in descriptive_test.cpp
  std::vector<double> x;
  for (int i = 0; i < 240; ++i) x.push_back(1000.0 * std::exp(1.5 * std::sin(1.3 * i + group) + 0.4 * group * std::cos(0.7 * i)));
  return x;
}

const std::vector<double> kG3 = {14.2, 25.8, 19.9, 41.3, 16.6, 21.0, 18.4, 28.7, 35.2};

TEST(Histogram, SturgesMatchesRHist) {
  // R: nclass.Sturges(g3) = 5;
  //    hist(g3, breaks = seq(min(g3), max(g3), length.out = 6), right = FALSE, include.lowest = TRUE)
  //    $breaks 14.2 19.62 25.04 30.46 35.88 41.3, $counts 3 2 2 1 1
  EXPECT_EQ(bin_count(kG3, BinRule::kSturges), 5u);
  const Histogram h = histogram(kG3, BinRule::kSturges);
  const std::vector<double> edges = {14.2, 19.62, 25.04, 30.46, 35.88, 41.3};
  ASSERT_EQ(h.edges.size(), edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) EXPECT_NEAR(h.edges[i], edges[i], 1e-12);
  EXPECT_EQ(h.counts, (std::vector<std::size_t>{3, 2, 2, 1, 1}));
}

TEST(Histogram, FreedmanDiaconisMatchesRHist) {
  // R: x <- cost(1, 0:239); k <- ceiling(diff(range(x)) / (2 * IQR(x) * 240^(-1/3)))  = 9
  //    hist(x, breaks = seq(min(x), max(x), length.out = k + 1), right = FALSE,
  //         include.lowest = TRUE)$counts = 111 32 23 21 17 12 10 6 8
  const std::vector<double> x = cost_sample(1);
  EXPECT_EQ(bin_count(x, BinRule::kFreedmanDiaconis), 9u);
  EXPECT_EQ(bin_count(x, BinRule::kSturges), 9u);  // nclass.Sturges: ceiling(log2(240) + 1)
  const Histogram h = histogram(x);
  EXPECT_EQ(h.counts, (std::vector<std::size_t>{111, 32, 23, 21, 17, 12, 10, 6, 8}));
  EXPECT_EQ(h.edges.front(), *std::min_element(x.begin(), x.end()));
  EXPECT_EQ(h.edges.back(), *std::max_element(x.begin(), x.end()));
}

TEST(Histogram, BinsAreHalfOpenAndTheLastIsClosed) {
  // Sturges for n = 5: ceil(log2(5) + 1) = 4 bins of width 1 over [0, 4].
  const std::vector<double> x = {0.0, 1.0, 1.0, 2.5, 4.0};
  const Histogram h = histogram(x, BinRule::kSturges);
  EXPECT_EQ(h.edges, (std::vector<double>{0.0, 1.0, 2.0, 3.0, 4.0}));
  // [0,1) holds 0; [1,2) holds both 1s (a value on an edge goes right); [3,4] holds the max.
  EXPECT_EQ(h.counts, (std::vector<std::size_t>{1, 2, 1, 1}));
}

TEST(Histogram, DegenerateSamples) {
  const Histogram empty = histogram(std::vector<double>{});
  EXPECT_TRUE(empty.edges.empty());
  EXPECT_TRUE(empty.counts.empty());

  const Histogram same = histogram(std::vector<double>{3.0, 3.0, 3.0});
  EXPECT_EQ(same.edges, (std::vector<double>{2.5, 3.5}));
  EXPECT_EQ(same.counts, (std::vector<std::size_t>{3}));

  // IQR = 0 but range > 0: Freedman-Diaconis falls back to Sturges instead of dividing by zero.
  const std::vector<double> spike = {1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 9.0};
  EXPECT_EQ(bin_count(spike, BinRule::kFreedmanDiaconis), 4u);  // ceil(log2(8) + 1)
  const Histogram h = histogram(spike);
  EXPECT_EQ(std::accumulate(h.counts.begin(), h.counts.end(), std::size_t{0}), spike.size());

  EXPECT_THROW(histogram(std::vector<double>{1.0, INFINITY}), ParameterError);
}

TEST(Histogram, BinCountIsCapped) {
  // A huge outlier over a tight bulk would ask Freedman-Diaconis for ~1e9 bins.
  std::vector<double> x(100, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i) * 1e-3;
  x.push_back(1e6);
  EXPECT_EQ(bin_count(x, BinRule::kFreedmanDiaconis), kMaxBins);
}

TEST(Histogram, SharedBinsAreHistogramsBuildingBlocks) {
  const std::vector<double> x = cost_sample(2);
  const Histogram h = histogram(x);
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  EXPECT_EQ(equal_width_edges(*lo, *hi, h.counts.size()), h.edges);
  EXPECT_EQ(bin_counts(x, h.edges), h.counts);
  EXPECT_EQ(bin_count(x, BinRule::kFreedmanDiaconis, 3), 3u);

  // Values outside the edges (e.g. rounded through log10 and back) fall in the first or last bin.
  const std::vector<double> edges = {1.0, 2.0, 3.0};
  EXPECT_EQ(bin_counts(std::vector<double>{0.999, 1.0, 2.0, 3.0, 3.001}, edges), (std::vector<std::size_t>{2, 3}));
  EXPECT_TRUE(bin_counts(x, std::vector<double>{}).empty());
}

}  // namespace
}  // namespace amp::stats
