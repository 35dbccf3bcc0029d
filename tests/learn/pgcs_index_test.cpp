#include "amp/learn/pgcs_index.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/rng.hpp"

namespace amp::learn {
namespace {

double criterion(const Eigen::Vector2d& x, const Eigen::Vector2d& mu, double s2, double prior) {
  return (x - mu).squaredNorm() / s2 + 2 * std::log(2 * std::numbers::pi * s2) - 2 * std::log(prior);
}

// Every cluster the search skips has a criterion above the limit, and the visited ones include
// the minimum: checked on random clusters (variances over four decades) and random queries.
TEST(PgcsIndex, SkipsOnlyClustersAboveTheLimit) {
  core::Rng rng(4);
  const int n = 300;
  std::vector<Eigen::Vector2d> mu(n);
  std::vector<double> s2(n), ps(n);
  std::vector<int> ids(n);
  for (int k = 0; k < n; ++k) {
    mu[k] = {rng.uniform(0, 10), rng.uniform(0, 10)};
    s2[k] = std::pow(10.0, rng.uniform(-3, 1));
    ps[k] = rng.uniform(0.01, 1.0);
    ids[k] = k;
  }
  const double scale = 0.37, log_scale = std::log(scale);
  PgcsIndex index(5);
  index.build(ids, mu, s2, ps);
  int skipped = 0;
  for (int q = 0; q < 200; ++q) {
    const Eigen::Vector2d x(rng.uniform(-2, 12), rng.uniform(-2, 12));
    double best = 1e300;
    for (int k = 0; k < n; ++k) best = std::min(best, criterion(x, mu[k], s2[k], scale * ps[k]));
    const double limit = best + 20.0;
    std::vector<char> seen(n, 0);
    index.search(x, log_scale, limit, [&](int k) {
      seen[k] = 1;
      return limit;
    });
    for (int k = 0; k < n; ++k) {
      if (!seen[k]) {
        EXPECT_GT(criterion(x, mu[k], s2[k], scale * ps[k]), limit) << k;
        ++skipped;
      }
    }
  }
  EXPECT_GT(skipped, 200 * n / 5);  // the search is selective (about a third skipped here)
}

TEST(PgcsIndex, TouchWidensTheBounds) {
  // One leaf of two clusters; cluster 0 moves far away and grows its prior: the search still finds it.
  std::vector<Eigen::Vector2d> mu{{0, 0}, {1, 0}};
  std::vector<double> s2{1, 1}, ps{0.5, 0.5};
  std::vector<int> ids{0, 1};
  PgcsIndex index(1);
  index.build(ids, mu, s2, ps);
  mu[0] = {50, 50};
  ps[0] = 0.9;
  index.touch(0, mu[0], s2[0], ps[0]);
  const Eigen::Vector2d x(50, 50);
  int found = -1;
  index.search(x, 0.0, criterion(x, mu[0], s2[0], ps[0]), [&](int k) {
    if (k == 0) found = 0;
    return 1e300;
  });
  EXPECT_EQ(found, 0);
}

}  // namespace
}  // namespace amp::learn
