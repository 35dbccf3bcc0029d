#include "amp/learn/kmeans.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/learn/elbow.hpp"

namespace amp::learn {
namespace {

Eigen::MatrixXd column(std::initializer_list<double> v) {
  Eigen::MatrixXd m(static_cast<Eigen::Index>(v.size()), 1);
  Eigen::Index i = 0;
  for (double x : v) m(i++, 0) = x;
  return m;
}

TEST(Lloyd, HandComputedIterations) {
  // Points 0, 1, 10, 11 from centres {0, 1}:
  //  pass 1: labels 0 1 1 1 -> centres 0, 22/3;  pass 2: labels 0 0 1 1 -> centres 0.5, 10.5;
  //  pass 3: no change. WCSS = 4 * 0.25 = 1.
  const KMeansFit fit = lloyd(column({0, 1, 10, 11}), column({0, 1}), 100);
  EXPECT_EQ(fit.labels, (std::vector<int>{0, 0, 1, 1}));
  EXPECT_DOUBLE_EQ(fit.centres(0, 0), 0.5);
  EXPECT_DOUBLE_EQ(fit.centres(1, 0), 10.5);
  EXPECT_DOUBLE_EQ(fit.wcss, 1.0);
  EXPECT_EQ(fit.iterations, 3);
  // Stopped after one pass: labels are re-derived from the centres of that pass (0, 22/3).
  const KMeansFit one = lloyd(column({0, 1, 10, 11}), column({0, 1}), 1);
  EXPECT_EQ(one.labels, (std::vector<int>{0, 0, 1, 1}));
  EXPECT_DOUBLE_EQ(one.centres(1, 0), 22.0 / 3.0);
}

TEST(Lloyd, EmptyClusterIsReseededSoKStaysK) {
  // Centre 100 wins no point on pass 1; it must jump to a point and end up owning some.
  const KMeansFit fit = lloyd(column({0, 1, 10, 11, 30, 31}), column({0, 100, 1}), 100);
  std::vector<int> counts(3, 0);
  for (int l : fit.labels) ++counts[static_cast<std::size_t>(l)];
  EXPECT_GT(*std::min_element(counts.begin(), counts.end()), 0);
  EXPECT_DOUBLE_EQ(fit.wcss, 0.5 * 3);  // the three pairs, each 2 * 0.25
}

TEST(KMeansPlusPlus, DrawByWeight) {
  const std::vector<double> w{0.0, 1.0, 0.0, 3.0};
  EXPECT_EQ(draw_by_weight(w, 0.0), 1u);
  EXPECT_EQ(draw_by_weight(w, 0.2499), 1u);
  EXPECT_EQ(draw_by_weight(w, 0.25), 3u);
  EXPECT_EQ(draw_by_weight(w, 0.999999), 3u);
  EXPECT_EQ(draw_by_weight(std::vector<double>{0.0, 0.0}, 0.6), 1u);  // all zero: uniform
}

TEST(KMeansPlusPlus, SeedPairFrequenciesMatchDSquaredSampling) {
  // Points 0, 1, 3, k = 2. First pick uniform; second with probability ~ D^2:
  //  first 0: D^2 = (1, 9)  -> P(1) = 0.1, P(3) = 0.9
  //  first 1: D^2 = (1, 4)  -> P(0) = 0.2, P(3) = 0.8
  //  first 3: D^2 = (9, 4)  -> P(0) = 9/13, P(1) = 4/13
  // P({0,1}) = (0.1 + 0.2)/3 = 0.1, P({0,3}) = (0.9 + 9/13)/3, P({1,3}) = (0.8 + 4/13)/3.
  const Eigen::MatrixXd x = column({0, 1, 3});
  core::Rng rng(7);
  constexpr int kDraws = 30000;
  std::map<std::pair<double, double>, int> freq;
  for (int i = 0; i < kDraws; ++i) {
    const Eigen::MatrixXd s = kmeans_pp_seeds(x, 2, rng);
    ++freq[{std::min(s(0, 0), s(1, 0)), std::max(s(0, 0), s(1, 0))}];
  }
  EXPECT_EQ(freq.size(), 3u);  // never the same point twice
  auto share = [&](double a, double b) { return freq[std::make_pair(a, b)] / double(kDraws); };
  EXPECT_NEAR(share(0, 1), 0.1, 0.015);  // 5 sigma of a proportion over 30000 draws
  EXPECT_NEAR(share(0, 3), (0.9 + 9.0 / 13.0) / 3.0, 0.015);
  EXPECT_NEAR(share(1, 3), (0.8 + 4.0 / 13.0) / 3.0, 0.015);
}

TEST(FitKMeans, RestartsReachTheBruteForceOptimum) {
  // 1-D, k = 2: the optimum is a split of the sorted points; try all 2^n labelings anyway.
  const Eigen::MatrixXd x = column({0.0, 0.4, 1.1, 3.0, 3.3, 7.5, 8.0, 8.2});
  double best = std::numeric_limits<double>::infinity();
  for (int mask = 1; mask < (1 << 8) - 1; ++mask) {
    double s[2] = {0, 0}, s2[2] = {0, 0}, n[2] = {0, 0};
    for (int i = 0; i < 8; ++i) {
      const int l = (mask >> i) & 1;
      s[l] += x(i, 0);
      s2[l] += x(i, 0) * x(i, 0);
      n[l] += 1;
    }
    best = std::min(best, s2[0] - s[0] * s[0] / n[0] + s2[1] - s[1] * s[1] / n[1]);
  }
  core::Rng rng(3);
  const KMeansFit fit = fit_kmeans(x, 2, 10, 100, rng);
  EXPECT_NEAR(fit.wcss, best, 1e-12);
  EXPECT_THROW(fit_kmeans(x, 9, 1, 10, rng), ParameterError);
  EXPECT_THROW(fit_kmeans(x, 0, 1, 10, rng), ParameterError);
}

TEST(KMeans, CurveIsTheWcssRatioAndElbowChoosesFromIt) {
  // Three tight 2-D groups of four at the corners of a near-equilateral triangle (side 20).
  Eigen::MatrixXd x(12, 2);
  for (int g = 0; g < 3; ++g) {
    for (int i = 0; i < 4; ++i) {
      x(4 * g + i, 0) = 10.0 * g + 0.3 * (i % 2);
      x(4 * g + i, 1) = (g == 1 ? 17.0 : 0.0) + 0.3 * (i / 2);
    }
  }
  core::Rng rng(11);
  const Clustering out = KMeans().cluster(x, rng);
  ASSERT_EQ(out.curve.size(), 10u);
  EXPECT_EQ(out.curve[0], 1.0);
  EXPECT_EQ(out.c, 3);
  EXPECT_EQ(elbow_choice(out.curve), 3);
  EXPECT_NEAR(out.curve[2], within_sum_of_squares(x, out.labels, out.centres) / total_sum_of_squares(x), 1e-12);
  EXPECT_EQ(out.labels, (std::vector<int>{0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2}));
}

TEST(KMeans, FewPointsAndIdenticalPoints) {
  core::Rng rng(1);
  // n = 2 < 3 candidate values of c: no elbow, one cluster.
  EXPECT_EQ(KMeans().cluster(column({0, 5}), rng).c, 1);
  // All equal: T = 0, the curve is all 0, no elbow.
  const Clustering same = KMeans().cluster(Eigen::MatrixXd::Constant(6, 2, 4.0), rng);
  EXPECT_EQ(same.c, 1);
  EXPECT_EQ(same.centres(0, 1), 4.0);
  EXPECT_THROW(KMeans(KMeansSettings{0, 10, 100}), ParameterError);
  EXPECT_THROW(KMeans().cluster(Eigen::MatrixXd(0, 2), rng), ParameterError);
}

}  // namespace
}  // namespace amp::learn
